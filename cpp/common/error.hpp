// Exception types of the core. Every function that can fail on user input throws one of these with a
// message that names the input and says how to fix it; the bindings map them to Python exceptions.
#pragma once

#include <stdexcept>
#include <string>

namespace hsm {

// Bad input from the user or the calling program (maps to Python ValueError).
class InputError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

// Valid input on which a computation could not succeed, e.g. an OCCT algorithm failed (maps to RuntimeError).
class ComputationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace hsm
