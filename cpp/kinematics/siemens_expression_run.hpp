// The evaluation of a compiled 840D expression (internal; included by siemens_expression.hpp).
#pragma once

#include "common/text.hpp"
#include "kinematics/gcode.hpp"

#include <algorithm>
#include <cmath>

namespace hsm::kinematics::detail {

template <class RParameter, class Lookup>
double runSiemensExpression(const SiemensExpression& e, long line, std::vector<double>& stack, RParameter&& rParameter,
                            Lookup&& lookup) {
  constexpr double kDegree = M_PI / 180.0;
  using Op = SiemensOperation;
  stack.clear();
  auto pop = [&]() {
    const double v = stack.back();
    stack.pop_back();
    return v;
  };
  for (const Op& op : e.operations) {
    switch (op.kind) {
      case Op::Number: stack.push_back(op.value); continue;
      case Op::RParameter: stack.push_back(rParameter(op.index)); continue;
      case Op::Variable: stack.push_back(lookup(e.names[static_cast<size_t>(op.index)], line)); continue;
      default: break;
    }
    if (op.kind >= Op::Atan2) {  // two arguments
      const double b = pop(), a = pop();
      stack.push_back(op.kind == Op::Atan2 ? std::atan2(a, b) / kDegree : op.kind == Op::MinValue ? std::min(a, b)
                                                                                               : std::max(a, b));
      continue;
    }
    if (op.kind >= Op::Sin || op.kind == Op::Negate || op.kind == Op::Not) {  // one argument
      const double a = pop();
      double v = 0.0;
      switch (op.kind) {
        case Op::Negate: v = -a; break;
        case Op::Not: v = a == 0.0; break;
        case Op::Sin: v = std::sin(a * kDegree); break;
        case Op::Cos: v = std::cos(a * kDegree); break;
        case Op::Tan: v = std::tan(a * kDegree); break;
        case Op::Asin:
        case Op::Acos:
          if (a < -1.0 || a > 1.0)
            throw ParseError(line, std::string(op.kind == Op::Asin ? "ASIN(" : "ACOS(") + number(a) +
                                       "): the argument must be within -1 to 1");
          v = (op.kind == Op::Asin ? std::asin(a) : std::acos(a)) / kDegree;
          break;
        case Op::Sqrt:
          if (a < 0.0) throw ParseError(line, "SQRT(" + number(a) + "): the argument must not be negative");
          v = std::sqrt(a);
          break;
        case Op::Pot: v = a * a; break;
        case Op::Abs: v = std::abs(a); break;
        case Op::Trunc: v = std::trunc(a); break;
        default: v = std::round(a); break;
      }
      stack.push_back(v);
      continue;
    }
    const double b = pop(), a = pop();
    double v = 0.0;
    switch (op.kind) {
      case Op::Add: v = a + b; break;
      case Op::Subtract: v = a - b; break;
      case Op::Multiply: v = a * b; break;
      case Op::Divide:
      case Op::IntegerDivide:
      case Op::Modulo:
        if (b == 0.0) throw ParseError(line, "division by zero in an expression");
        v = op.kind == Op::Divide ? a / b : op.kind == Op::IntegerDivide ? std::trunc(a / b) : std::fmod(a, b);
        break;
      case Op::Equal: v = a == b; break;
      case Op::NotEqual: v = a != b; break;
      case Op::Less: v = a < b; break;
      case Op::Greater: v = a > b; break;
      case Op::LessEqual: v = a <= b; break;
      case Op::GreaterEqual: v = a >= b; break;
      case Op::And: v = a != 0.0 && b != 0.0; break;
      case Op::Or: v = a != 0.0 || b != 0.0; break;
      default: v = (a != 0.0) != (b != 0.0); break;  // Xor
    }
    stack.push_back(v);
  }
  return stack.empty() ? 0.0 : stack.back();
}

}  // namespace hsm::kinematics::detail
