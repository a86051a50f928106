// The 840D's variables and arithmetic (internal): R parameters (R0 … R999), variables declared by DEF (REAL,
// INT, BOOL, CHAR, STRING, AXIS, FRAME), assignments to them and to addresses (X=R1+5, Z=_Z_HOME, CR=R3/2),
// expressions with + - * / DIV MOD, parentheses and the standard functions (SIN COS TAN ASIN ACOS ATAN2 SQRT
// POT ABS TRUNC ROUND MINVAL MAXVAL, AC()), as the SINUMERIK 840D sl Job Planning manual ("Flexible NC
// programming") gives them. A line that uses them is rewritten into plain words for the lexer, its assignments
// applied in the order written. Not read here: labels, jumps and loops, IC() on an axis, string arithmetic.
#pragma once

#include "kinematics/siemens_expression.hpp"

#include <array>
#include <map>
#include <vector>
#include <string>
#include <string_view>

namespace hsm::kinematics::detail {

inline constexpr int kSiemensRParameters = 1000;

// A line of the 840D's language compiled once (its assignments, declarations and computed address values), to be
// run as often as a loop or a call runs it.
struct SiemensLine {
  struct Piece {
    enum Kind : std::uint8_t { Text, Assign, Address, Declare } kind = Text;
    std::string text;            // Text: as written; Assign, Declare: the variable; Address: the address (X, CR…)
    SiemensExpression value;     // Assign, Address, Declare (with hasValue)
    bool hasValue = true;
  };
  std::vector<Piece> pieces;
  bool asWritten = false;  // nothing to compute: the lexer reads the line as it is
};

class SiemensVariables {
public:
  SiemensVariables() { r_.fill(0.0); }

  // A line in the 840D's language as plain words; `out` holds the rewritten text when the line needed it.
  std::string_view substitute(std::string_view raw, long line, std::string& out);
  // The same in two steps: compiled once, run each time the line runs.
  void compile(std::string_view raw, long line, SiemensLine& out) const;
  std::string_view run(const SiemensLine& compiled, std::string_view raw, long line, std::string& out);
  // An expression (or a condition: 1 true, 0 false) from `p`, which is left after it.
  double evaluate(const char*& p, const char* end, long line) const;
  double evaluate(const SiemensExpression& e, long line) const;
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
  void compileDeclaration(const char*& p, const char* end, long line, SiemensLine& out) const;
  bool plainAssignments(std::string_view raw) const;

  std::array<double, kSiemensRParameters> r_{};
  std::vector<std::map<std::string, double>> scopes_{1};  // DEF variables (in capitals) of each program level
  mutable std::vector<double> stack_;                     // the expressions' scratch
};

}  // namespace hsm::kinematics::detail
