// LinuxCNC's parameters and expressions (internal): numbered (#1 … #5602), named local (#<depth>) and global
// (#<_depth>) parameters, and the bracketed expressions with their operators and functions, as LinuxCNC 2.9's
// rs274ngc reads them. A line that uses them is rewritten into plain words (X12.5) for the lexer, its
// parameter settings applied after the whole line is read, as rs274ngc does.
// Fanuc's Macro B is the same language with three differences, taken here from the same code: a variable may
// be vacant (#0, a local or common never set: 0 in arithmetic, not equal to 0 in EQ/NE, a word given a vacant
// value is left out of its block), an assignment's right side needs no brackets (#1=#2+3), and the variables
// are Fanuc's (#1-#33 local to a G65 call, #100-#199 and #500-#999 common, system variables by number).
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics::detail {

inline constexpr int kMaxNumberedParameter = 5602;
inline constexpr int kSubroutineArguments = 30;  // #1 … #30 are a subroutine's arguments, local to its call
inline constexpr int kMacroLocals = 33;          // Fanuc: #1 … #33 are local to a G65 call

enum class ParameterLanguage { LinuxCnc, MacroB };

class NgcParameters {
public:
  explicit NgcParameters(ParameterLanguage language = ParameterLanguage::LinuxCnc);

  bool macroB() const { return language_ == ParameterLanguage::MacroB; }
  // Macro B: a vacant variable's value (a NaN, never a computed result: expressions refuse those).
  static bool vacant(double value) { return value != value; }
  // Macro B: where the tool is, for the position variables (#5001…, #5021…, #5041…), in program units.
  void setPositions(const double (*positions)[3]) { positions_ = positions; }

  // Throws ParseError (naming the line and the fix) for a number out of range or a name never set.
  double numbered(int number, long line) const;
  void setNumbered(int number, double value, long line);
  double named(const std::string& name, long line) const;  // name in lower case, without #< >
  bool exists(const std::string& name) const;
  void setNamed(const std::string& name, double value);

  // A subroutine call: #1 … #30 and the named locals saved, the arguments given set, the rest 0.
  void enterCall(const std::vector<double>& arguments);
  void leaveCall();
  // Macro B, a G65 call: #1 … #33 saved, those given set (index 0 is #1; vacant where not given).
  void enterMacroCall(const std::array<double, kMacroLocals>& arguments);
  int depth() const { return static_cast<int>(locals_.size()) - 1; }

private:
  double systemVariable(int number, long line) const;
  void setSystemVariable(int number, double value, long line);

  ParameterLanguage language_;
  const double (*positions_)[3] = nullptr;  // block end (work), machine, work: three rows of X Y Z
  std::array<double, kMaxNumberedParameter + 1> numbered_{};
  std::map<std::string, double> globals_;
  std::vector<std::map<std::string, double>> locals_;           // one scope per call, the program's first
  std::vector<std::array<double, kMacroLocals>> saved_;  // the caller's #1 … #30 (#33 in Macro B)
};

// Reads values and expressions from a line of text (spaces ignored, letters in any case).
class NgcExpressionReader {
public:
  NgcExpressionReader(const NgcParameters& parameters, long line) : parameters_(parameters), line_(line) {}

  // A real value at `p` (a number, #parameter, [expression], a unary function, with an optional sign); p moves
  // past it. Throws ParseError on malformed text or a value that is not a finite number.
  double value(const char*& p, const char* end) const;
  // Macro B: an expression without brackets up to the end of the text or a comment (#1=#2+3*#4).
  double toEnd(const char*& p, const char* end) const;
  // A parameter reference after its '#' (a number, <name>, #…, [expression]): its number, or its name in `name`.
  int reference(const char*& p, const char* end, std::string& name) const;

private:
  double expression(const char*& p, const char* end) const;  // after '[', up to and past ']'
  // Operands and operators from p up to `closing` (']' is passed; '\0': the end of the text or a comment).
  double operations(const char*& p, const char* end, char closing) const;
  double unaryFunction(const std::string& name, const char*& p, const char* end) const;
  double apply(int op, double a, double b) const;  // an operator of the expression (its enum in the .cpp)
  [[noreturn]] void fail(const std::string& message) const;

  const NgcParameters& parameters_;
  long line_;
};

// A line in LinuxCNC's language as plain words: values computed, comments dropped, parameter settings
// (#1=…, #<x>=…) applied to `parameters` after the line is read. Lines without '#' or '[' come back unchanged.
// `out` holds the rewritten text when the line needed it; the returned view is into `raw` or `out`.
std::string_view substituteParameters(std::string_view raw, long line, NgcParameters& parameters, std::string& out);

// True when the line needs rewriting (a '#' or a '[' outside comments).
bool usesParameters(std::string_view raw);

// Skips blanks at p.
inline void skipBlanks(const char*& p, const char* end) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
}

}  // namespace hsm::kinematics::detail
