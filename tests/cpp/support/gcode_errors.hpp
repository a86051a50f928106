// The message of the ParseError a program gives when read, or "" when it reads: for tests of the reader.
#pragma once

#include "kinematics/gcode.hpp"

#include <string>

namespace hsm::test {

inline std::string errorOf(const std::string& program, const kinematics::ReaderOptions& options = {}) {
  try {
    kinematics::readProgram(program, options);
  } catch (const kinematics::ParseError& error) {
    return error.what();
  }
  return "";
}

}  // namespace hsm::test
