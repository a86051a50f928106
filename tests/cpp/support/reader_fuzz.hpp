// Mutations of a seed program fed to the G-code reader: each is read (every block's ends finite) or refused with
// an InputError, never a crash or an endless run. For the fuzz tests of each dialect's language.
#pragma once

#include "kinematics/gcode.hpp"
#include "support/mutation.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace hsm::test {

struct MutantOutcome {
  int read = 0, refused = 0;
};

inline MutantOutcome readMutants(const std::string& seed, const std::string& alphabet,
                                 const kinematics::ReaderOptions& options, unsigned seedValue, int rounds = 5000) {
  std::mt19937 random(seedValue);
  MutantOutcome outcome;
  for (int round = 0; round < rounds; ++round) {
    const std::string program = mutated(seed, alphabet, random);
    try {
      for (const kinematics::Block& b : kinematics::readProgram(program, options))
        EXPECT_TRUE(b.start.allFinite() && b.end.allFinite()) << program;
      ++outcome.read;
    } catch (const InputError&) {
      ++outcome.refused;
    }
  }
  return outcome;
}

// Over a hundred mutants read and over a hundred refused: the mutations reach both sides of the reader.
inline void expectReadAndRefused(const std::string& seed, const std::string& alphabet,
                                 const kinematics::ReaderOptions& options, unsigned seedValue) {
  const MutantOutcome mutants = readMutants(seed, alphabet, options, seedValue);
  EXPECT_GT(mutants.read, 100);
  EXPECT_GT(mutants.refused, 100);
}

}  // namespace hsm::test
