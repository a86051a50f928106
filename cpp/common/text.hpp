// Numbers in messages: as people read them (6 significant digits, "1e-09", "inf"), not std::to_string's
// fixed six decimals that print 1e-9 as "0.000000".
#pragma once

#include <sstream>
#include <string>

namespace hsm {

inline std::string number(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

inline std::string mm(double value) { return number(value) + " mm"; }

}  // namespace hsm
