#include "kinematics/siemens_expression.hpp"

#include "common/ascii.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/siemens_text.hpp"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <string_view>

namespace hsm::kinematics::detail {

namespace {
// Recursive descent over the 840D's arithmetic and conditions: either := both {(OR|XOR) both}; both := negation
// {AND negation}; negation := NOT negation | comparison; comparison := sum [(==|<>|<|>|<=|>=) sum]; sum := product
// {(+|-) product}; product := unary {(*|/|DIV|MOD) unary}; unary := [+|-] primary; primary := number | variable |
// (either) | FUNCTION(sum[, sum]). Each emits its operations after its operands'.
class Compiler {
public:
  Compiler(SiemensExpression& out, long line) : out_(out), line_(line) {}

  void either(const char*& p, const char* end) {
    both(p, end);
    for (std::string op = operatorWord(p, end); op == "OR" || op == "XOR"; op = operatorWord(p, end)) {
      skipWord(p, end);
      both(p, end);
      emit(op == "OR" ? SiemensOperation::Or : SiemensOperation::Xor);
    }
  }

private:
  using Op = SiemensOperation;

  [[noreturn]] void fail(const std::string& message) const { throw ParseError(line_, message); }
  void emit(Op::Kind kind, int index = 0, double value = 0.0) { out_.operations.push_back(Op{kind, index, value}); }

  // The word of letters at `p` (after blanks), in capitals, without moving `p`.
  static std::string operatorWord(const char* p, const char* end) {
    skipBlanks(p, end);
    std::string word;
    while (p < end && isAsciiLetter(*p) && word.size() < 4) word += asciiUpper(*p++);
    return (p < end && siemens_text::nameChar(*p)) ? std::string() : word;
  }
  static void skipWord(const char*& p, const char* end) {
    skipBlanks(p, end);
    while (p < end && isAsciiLetter(*p)) ++p;
  }

  void both(const char*& p, const char* end) {
    negation(p, end);
    while (operatorWord(p, end) == "AND") {
      skipWord(p, end);
      negation(p, end);
      emit(Op::And);
    }
  }

  void negation(const char*& p, const char* end) {
    if (operatorWord(p, end) == "NOT") {
      skipWord(p, end);
      negation(p, end);
      emit(Op::Not);
      return;
    }
    comparison(p, end);
  }

  void comparison(const char*& p, const char* end) {
    sum(p, end);
    const char* q = p;
    skipBlanks(q, end);
    if (q >= end) return;
    const std::string_view two = q + 1 < end ? std::string_view(q, 2) : std::string_view();
    Op::Kind kind;
    if (two == "==") kind = Op::Equal;
    else if (two == "<>") kind = Op::NotEqual;
    else if (two == "<=") kind = Op::LessEqual;
    else if (two == ">=") kind = Op::GreaterEqual;
    else if (*q == '<') kind = Op::Less;
    else if (*q == '>') kind = Op::Greater;
    else return;
    p = q + (kind == Op::Less || kind == Op::Greater ? 1 : 2);
    sum(p, end);
    emit(kind);
  }

  void sum(const char*& p, const char* end) {
    product(p, end);
    for (;;) {
      const char* q = p;
      skipBlanks(q, end);
      if (q >= end || (*q != '+' && *q != '-')) return;
      const char op = *q++;
      p = q;
      product(p, end);
      emit(op == '+' ? Op::Add : Op::Subtract);
    }
  }

  void product(const char*& p, const char* end) {
    unary(p, end);
    for (;;) {
      const char* q = p;
      skipBlanks(q, end);
      Op::Kind kind;
      if (q < end && (*q == '*' || *q == '/')) {
        kind = *q++ == '*' ? Op::Multiply : Op::Divide;
      } else if (q + 3 <= end && isAsciiLetter(*q)) {
        const char* r = q;
        const std::string word = siemens_text::name(r, end);
        if (word != "DIV" && word != "MOD") return;
        kind = word == "DIV" ? Op::IntegerDivide : Op::Modulo;
        q = r;
      } else {
        return;
      }
      p = q;
      unary(p, end);
      emit(kind);
    }
  }

  void unary(const char*& p, const char* end) {
    skipBlanks(p, end);
    if (p < end && (*p == '-' || *p == '+')) {
      const char sign = *p++;
      unary(p, end);
      if (sign == '-') emit(Op::Negate);
      return;
    }
    primary(p, end);
  }

  void primary(const char*& p, const char* end) {
    skipBlanks(p, end);
    if (p >= end) fail("a value is missing at the end of the line");
    if (*p == '(') {
      ++p;
      either(p, end);
      close(p, end);
      return;
    }
    if (isAsciiDigit(*p) || *p == '.') {
      double v = 0.0;
      const auto parsed = fast_float::from_chars(p, end, v, fast_float::chars_format::fixed);
      if (parsed.ec != std::errc()) fail("'" + std::string(p, std::min<size_t>(end - p, 16)) + "' is not a number");
      p = parsed.ptr;
      if (p < end && (*p == 'E' || *p == 'e') && p + 1 < end &&
          (isAsciiDigit(p[1]) || p[1] == '-' || p[1] == '+' || p[1] == 'X'))
        fail("a number with an exponent ('" + std::string(parsed.ptr - 1, std::min<size_t>(end - parsed.ptr + 1, 8)) +
             "'): not read; write the number in full");
      emit(Op::Number, 0, v);
      return;
    }
    if (!isAsciiLetter(*p) && *p != '_') fail(std::string("unexpected character '") + *p + "' in an expression");
    const std::string name = siemens_text::name(p, end);
    const char* q = p;
    skipBlanks(q, end);
    if (q < end && *q == '(') {
      p = q + 1;
      return function(name, p, end);
    }
    if (siemens_text::isRParameter(name)) return emit(Op::RParameter, std::stoi(name.substr(1)));
    const auto known = std::find(out_.names.begin(), out_.names.end(), name);
    emit(Op::Variable, static_cast<int>(known - out_.names.begin()));
    if (known == out_.names.end()) out_.names.push_back(name);
  }

  void close(const char*& p, const char* end) const {
    skipBlanks(p, end);
    if (p >= end || *p != ')') fail("'(' is not closed: add ')'");
    ++p;
  }

  void function(const std::string& name, const char*& p, const char* end) {
    struct Known {
      const char* name;
      Op::Kind kind;
    };
    static constexpr Known kOne[] = {{"SIN", Op::Sin},   {"COS", Op::Cos},   {"TAN", Op::Tan},     {"ASIN", Op::Asin},
                                     {"ACOS", Op::Acos}, {"SQRT", Op::Sqrt}, {"POT", Op::Pot},     {"ABS", Op::Abs},
                                     {"TRUNC", Op::Trunc}, {"ROUND", Op::Round}};
    static constexpr Known kTwo[] = {{"ATAN2", Op::Atan2}, {"MINVAL", Op::MinValue}, {"MAXVAL", Op::MaxValue}};
    if (name == "IC") fail("IC() gives one axis an incremental value (X=IC(5)): it is not a value of an expression");
    sum(p, end);
    skipBlanks(p, end);
    for (const Known& k : kTwo) {
      if (name != k.name) continue;
      if (p >= end || *p != ',') fail(name + " takes two arguments: " + name + "(a, b)");
      ++p;
      sum(p, end);
      close(p, end);
      return emit(k.kind);
    }
    close(p, end);
    if (name == "AC") return;  // an absolute value: as it is
    for (const Known& k : kOne)
      if (name == k.name) return emit(k.kind);
    fail("'" + name + "(' is not an 840D function read here (SIN COS TAN ASIN ACOS ATAN2 SQRT POT ABS TRUNC ROUND "
                      "MINVAL MAXVAL AC)");
  }

  SiemensExpression& out_;
  long line_;
};
}  // namespace

void compileSiemensExpression(const char*& p, const char* end, long line, SiemensExpression& out) {
  out.operations.clear();
  out.names.clear();
  Compiler(out, line).either(p, end);
}

}  // namespace hsm::kinematics::detail
