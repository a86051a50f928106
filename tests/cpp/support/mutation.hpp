// Random edits of a program text, for the tests that feed the reader and the simulator with broken programs.
#pragma once

#include <random>
#include <string>

namespace hsm::test {

// 1 to 8 single-character edits (insert, erase or replace) with characters of `alphabet`.
inline std::string mutated(std::string program, const std::string& alphabet, std::mt19937& random) {
  const int edits = 1 + static_cast<int>(random() % 8);
  for (int e = 0; e < edits; ++e) {
    const size_t at = random() % (program.size() + 1);
    switch (random() % 3) {
      case 0: program.insert(at, 1, alphabet[random() % alphabet.size()]); break;
      case 1: if (at < program.size()) program.erase(at, 1); break;
      default: if (at < program.size()) program[at] = alphabet[random() % alphabet.size()];
    }
  }
  return program;
}

}  // namespace hsm::test
