// What the BREP harnesses share: a fuzz input is a first line of numbers (the parameters the harness
// hands on, each clamped to the range a user may type) and BREP text after it.
#pragma once

#include "common/error.hpp"

#include <Standard_Failure.hxx>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace hsm::fuzz {

struct Input {
  std::vector<double> numbers;  // from the first line; missing ones take the harness's defaults
  std::string brep;             // the rest

  double number(size_t index, double fallback) const {
    return index < numbers.size() ? numbers[index] : fallback;
  }
};

inline Input split(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const size_t newline = text.find('\n');
  Input input;
  std::istringstream header(text.substr(0, newline));
  double value = 0.0;
  while (input.numbers.size() < 8 && header >> value) input.numbers.push_back(value);
  input.brep = newline == std::string::npos ? std::string() : text.substr(newline + 1);
  return input;
}

[[noreturn]] inline void finding(const char* harness, const char* what) {
  std::fprintf(stderr, "%s finding: %s\n", harness, what);
  std::abort();
}

// Runs `body`; the core's own errors are the expected answers to bad input, anything else is a finding.
template <class Body>
void expectOnlyCoreErrors(const char* harness, Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const ComputationError&) {
  } catch (const Standard_Failure& failure) {
    std::fprintf(stderr, "OCCT: %s\n", failure.GetMessageString());
    finding(harness, "an OCCT exception escaped the core");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    finding(harness, "an exception that is not one of the core's");
  }
}

}  // namespace hsm::fuzz
