// The 840D's variables and arithmetic (internal): R parameters (R0 … R999), variables declared by DEF (REAL,
// INT, BOOL, CHAR, STRING, AXIS, FRAME), assignments to them and to addresses (X=R1+5, Z=_Z_HOME, CR=R3/2),
// expressions with + - * / DIV MOD, parentheses and the standard functions (SIN COS TAN ASIN ACOS ATAN2 SQRT
// POT ABS TRUNC ROUND MINVAL MAXVAL, AC()), as the SINUMERIK 840D sl Job Planning manual ("Flexible NC
// programming") gives them. A line that uses them is rewritten into plain words for the lexer, its assignments
// applied in the order written. Not read here: labels, jumps and loops, IC() on an axis, string arithmetic.
#pragma once

#include <array>
#include <map>
#include <vector>
#include <string>
#include <string_view>

namespace hsm::kinematics::detail {

inline constexpr int kSiemensRParameters = 1000;

class SiemensVariables {
public:
  SiemensVariables() { r_.fill(0.0); }

  // A line in the 840D's language as plain words; `out` holds the rewritten text when the line needed it.
  std::string_view substitute(std::string_view raw, long line, std::string& out);
  // An expression (or a condition: 1 true, 0 false) from `p`, which is left after it.
  double evaluate(const char*& p, const char* end, long line) const;
  bool isVariable(const std::string& name) const;
  double get(const std::string& name, long line) const;
  void set(const std::string& name, double value, long line);
  // A subprogram call's own variables: its parameters are declared in it; they are gone when it returns.
  void enterCall() { scopes_.emplace_back(); }
  void leaveCall() {
    if (scopes_.size() > 1) scopes_.pop_back();
  }
  void declareLocal(const std::string& name, double value) { scopes_.back()[name] = value; }

private:
  class Reader;  // the expression reader (in the .cpp)

  void declare(const char*& p, const char* end, long line);
  bool plainAssignments(std::string_view raw) const;

  std::array<double, kSiemensRParameters> r_{};
  std::vector<std::map<std::string, double>> scopes_{1};  // DEF variables (in capitals) of each program level
};

}  // namespace hsm::kinematics::detail
