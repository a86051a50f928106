// The 840D's arithmetic and conditions (internal), as the SINUMERIK 840D sl Job Planning manual ("Flexible NC
// programming") gives them: + - * / DIV MOD, parentheses, == <> < > <= >=, AND OR XOR NOT, and the functions SIN
// COS TAN ASIN ACOS ATAN2 (degrees) SQRT POT ABS TRUNC ROUND MINVAL MAXVAL AC(). Compiled once into postfix
// operations, so that a loop runs a line's expressions without reading its text again; the values of variables
// are looked up when it runs (siemens_variables.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hsm::kinematics::detail {

struct SiemensOperation {
  enum Kind : std::uint8_t {
    Number, RParameter, Variable, Negate, Add, Subtract, Multiply, Divide, IntegerDivide, Modulo,
    Equal, NotEqual, Less, Greater, LessEqual, GreaterEqual, And, Or, Xor, Not,
    Sin, Cos, Tan, Asin, Acos, Sqrt, Pot, Abs, Trunc, Round, Atan2, MinValue, MaxValue
  };
  Kind kind = Number;
  int index = 0;       // an R parameter's number, or a variable's name in the expression's `names`
  double value = 0.0;  // a Number's
};

struct SiemensExpression {
  std::vector<SiemensOperation> operations;
  std::vector<std::string> names;  // the variables it reads, in capitals
};

// Compiles the expression (or condition) from `p`, which is left after it. ParseError at `line` for what is not
// one: a missing value, an unknown function, an exponent, IC().
void compileSiemensExpression(const char*& p, const char* end, long line, SiemensExpression& out);

// The operations' result given the values of the R parameters and variables (`lookup(name, line)`); ParseError
// at `line` for a division by zero or a function's argument out of its domain. `stack` is scratch.
template <class RParameter, class Lookup>
double runSiemensExpression(const SiemensExpression& e, long line, std::vector<double>& stack, RParameter&& rParameter,
                            Lookup&& lookup);

}  // namespace hsm::kinematics::detail

#include "kinematics/siemens_expression_run.hpp"
