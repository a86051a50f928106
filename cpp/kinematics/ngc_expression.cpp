#include "kinematics/ngc_expression.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/gcode_lexer.hpp"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace hsm::kinematics::detail {

namespace {
constexpr double kDegree = M_PI / 180.0;
constexpr double kIntegerTolerance = 1e-4;  // rs274ngc's: a parameter number or an L count this close to an integer

constexpr auto isLetter = isAsciiLetter;
constexpr auto isDigit = isAsciiDigit;
constexpr auto lower = asciiLower;

// The operators of a bracketed expression, in rs274ngc's precedence (higher binds first, all left-associative).
enum class Op { Power, Times, Divide, Modulo, Plus, Minus, Eq, Ne, Gt, Ge, Lt, Le, And, Or, Xor, None };

int precedence(Op op) {
  switch (op) {
    case Op::Power: return 6;
    case Op::Times: case Op::Divide: case Op::Modulo: return 5;
    case Op::Plus: case Op::Minus: return 4;
    case Op::Eq: case Op::Ne: case Op::Gt: case Op::Ge: case Op::Lt: case Op::Le: return 3;
    default: return 2;
  }
}

Op wordOperator(const std::string& word) {
  static const std::pair<const char*, Op> words[] = {{"mod", Op::Modulo}, {"eq", Op::Eq}, {"ne", Op::Ne},
                                                     {"gt", Op::Gt},      {"ge", Op::Ge}, {"lt", Op::Lt},
                                                     {"le", Op::Le},      {"and", Op::And}, {"or", Op::Or},
                                                     {"xor", Op::Xor}};
  for (const auto& [name, op] : words)
    if (word == name) return op;
  return Op::None;
}

// Macro B: a vacant value counts as 0 in arithmetic and functions.
double orZero(double v) { return v != v ? 0.0 : v; }

std::string quoted(const char* p, const char* end) {
  const char* stop = p;
  while (stop < end && stop - p < 24) ++stop;
  return std::string(p, stop);
}
}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Parameters

namespace {
constexpr double kVacant = std::numeric_limits<double>::quiet_NaN();

// Macro B's variables a program may set: locals, the two common ranges, and the system variables that change
// nothing the simulation sees (timers, part counters, tool offsets) or that it refuses by name.
bool macroCommon(int n) { return (n >= 1 && n <= kMacroLocals) || (n >= 100 && n <= 199) || (n >= 500 && n <= 999); }

std::string fanucRange() { return "Fanuc's variables are #1-#33 (local), #100-#199 and #500-#999 (common) and system ones"; }
}  // namespace

NgcParameters::NgcParameters(ParameterLanguage language) : language_(language) {
  numbered_.fill(0.0);
  if (macroB())  // vacant until set: locals and commons at power-on (#500… are kept by the control: unknown here)
    for (int n = 1; n <= 999; ++n)
      if (macroCommon(n)) numbered_[static_cast<size_t>(n)] = kVacant;
  locals_.emplace_back();
}

double NgcParameters::systemVariable(int number, long line) const {
  if (number == 0) return kVacant;
  const bool position = (number >= 5001 && number <= 5003) || (number >= 5021 && number <= 5023) ||
                        (number >= 5041 && number <= 5043);
  if (position && positions_ != nullptr) return positions_[(number % 100 - 1) / 20][number % 10 - 1];
  if ((number >= 4001 && number <= 4130) || (number >= 5001 && number <= 5106))
    throw ParseError(line, "#" + std::to_string(number) + " (the control's modal state or a position of another "
                               "axis) is not simulated: write the value in the program instead");
  return numbered_[static_cast<size_t>(number)];
}

void NgcParameters::setSystemVariable(int number, double value, long line) {
  if (number == 3000)
    throw ParseError(line, "the program raises alarm #3000 = " + hsm::number(value) + ": it stops here on the machine");
  const bool harmless = number == 3001 || number == 3002 || number == 3004 || number == 3006 || number == 3901 ||
                        number == 3902 || (number >= 2001 && number <= 2800);
  if (!harmless)
    throw ParseError(line, "#" + std::to_string(number) + " cannot be set here: " + fanucRange() +
                               " (timers #3001/#3002, counters #3901/#3902, tool offsets #2001-#2800); a work offset "
                               "set through its variable would move the program, which the simulator does not read");
  numbered_[static_cast<size_t>(number)] = value;
}

double NgcParameters::numbered(int number, long line) const {
  if (number < 0 || number > kMaxNumberedParameter)
    throw ParseError(line, "#" + hsm::number(number) + " is not a parameter: " +
                               (macroB() ? fanucRange() + " up to #" : std::string("LinuxCNC's numbered parameters are #1 to #")) +
                               std::to_string(kMaxNumberedParameter));
  if (macroB() && !macroCommon(number)) return systemVariable(number, line);
  return numbered_[static_cast<size_t>(number)];
}

void NgcParameters::setNumbered(int number, double value, long line) {
  if (macroB() && !macroCommon(number) && number >= 0 && number <= kMaxNumberedParameter)
    return setSystemVariable(number, value, line);
  if (number < 1 || number > kMaxNumberedParameter)
    throw ParseError(line, "#" + hsm::number(number) + " cannot be set: " +
                               (macroB() ? fanucRange() : "LinuxCNC's numbered parameters are #1 to #" +
                                                              std::to_string(kMaxNumberedParameter)));
  numbered_[static_cast<size_t>(number)] = value;
}

double NgcParameters::named(const std::string& name, long line) const {
  if (name.rfind("_hal[", 0) == 0 || name.rfind("_ini[", 0) == 0)
    throw ParseError(line, "#<" + name + "> reads the machine's " + (name[1] == 'h' ? "HAL" : "INI file") +
                               ", which is not simulated: write its value in the program instead");
  const auto& scope = name.front() == '_' ? globals_ : locals_.back();
  const auto found = scope.find(name);
  if (found == scope.end())
    throw ParseError(line, "#<" + name + "> is read before it is set: set it first (#<" + name +
                               "> = ...)" + (name.front() == '_' ? " or check its spelling" : ", or use a global #<_" + name + ">"));
  return found->second;
}

bool NgcParameters::exists(const std::string& name) const {
  const auto& scope = name.front() == '_' ? globals_ : locals_.back();
  return scope.count(name) > 0;
}

void NgcParameters::setNamed(const std::string& name, double value) {
  (name.front() == '_' ? globals_ : locals_.back())[name] = value;
}

void NgcParameters::enterCall(const std::vector<double>& arguments) {
  std::array<double, kMacroLocals> saved{};
  for (int i = 0; i < kSubroutineArguments; ++i) {
    saved[static_cast<size_t>(i)] = numbered_[static_cast<size_t>(i + 1)];
    numbered_[static_cast<size_t>(i + 1)] = i < static_cast<int>(arguments.size()) ? arguments[static_cast<size_t>(i)] : 0.0;
  }
  saved_.push_back(saved);
  locals_.emplace_back();
}

void NgcParameters::enterMacroCall(const std::array<double, kMacroLocals>& arguments) {
  std::array<double, kMacroLocals> saved{};
  for (size_t i = 0; i < arguments.size(); ++i) {
    saved[i] = numbered_[i + 1];
    numbered_[i + 1] = arguments[i];
  }
  saved_.push_back(saved);
  locals_.emplace_back();
}

void NgcParameters::leaveCall() {
  if (saved_.empty()) return;
  const int count = macroB() ? kMacroLocals : kSubroutineArguments;
  for (int i = 0; i < count; ++i) numbered_[static_cast<size_t>(i + 1)] = saved_.back()[static_cast<size_t>(i)];
  saved_.pop_back();
  locals_.pop_back();
}

// ---------------------------------------------------------------------------------------------------------
// Expressions

void NgcExpressionReader::fail(const std::string& message) const { throw ParseError(line_, message); }

int NgcExpressionReader::reference(const char*& p, const char* end, std::string& name) const {
  skipBlanks(p, end);
  name.clear();
  if (p < end && *p == '<') {
    const char* close = static_cast<const char*>(std::memchr(p, '>', static_cast<size_t>(end - p)));
    if (!close) fail("'#<' has no closing '>': write a named parameter as #<name>");
    for (const char* c = p + 1; c < close; ++c)
      if (*c != ' ' && *c != '\t') name += lower(*c);
    if (name.empty()) fail("'#<>' names no parameter: write a name between < and >");
    p = close + 1;
    return -1;
  }
  const double number = value(p, end);
  if (!std::isfinite(number))  // Macro B: a vacant variable as the number (#[#100] with #100 never set)
    fail("#[...] names no parameter: its number is vacant (a variable never set); set it first");
  const double rounded = std::round(number);
  if (std::abs(number - rounded) > kIntegerTolerance)
    fail("#" + hsm::number(number) + " is not a parameter: a parameter number is an integer");
  if (rounded < 0 || rounded > kMaxNumberedParameter)
    fail("#" + std::to_string(static_cast<long long>(rounded)) + " is not a parameter: " +
         (parameters_.macroB() ? std::string("Fanuc's variables are #0 to #") : "LinuxCNC's numbered parameters are #1 to #") +
         std::to_string(kMaxNumberedParameter));
  return static_cast<int>(rounded);
}

double NgcExpressionReader::value(const char*& p, const char* end) const {
  skipBlanks(p, end);
  if (p >= end) fail("a value is missing at the end of the line: give a number, a #parameter or a [expression]");
  const char c = *p;
  const char next = p + 1 < end ? p[1] : '\0';
  if (c == '[') {
    ++p;
    return expression(p, end);
  }
  if (c == '#') {
    ++p;
    std::string name;
    const int number = reference(p, end, name);
    return number < 0 ? parameters_.named(name, line_) : parameters_.numbered(number, line_);
  }
  if ((c == '-' || c == '+') && !isDigit(next) && next != '.') {
    ++p;
    const double v = value(p, end);
    return c == '-' ? -v : v;
  }
  if (isLetter(c)) {
    std::string name;
    while (p < end && isLetter(*p)) name += lower(*p++);
    return unaryFunction(name, p, end);
  }
  const char* digits = (c == '-' || c == '+') ? p + 1 : p;
  if (!(digits < end && (isDigit(*digits) || *digits == '.')))
    fail("'" + quoted(p, end) + "' is not a value: give a number, a #parameter or a [expression]");
  double v = 0.0;
  const auto parsed = fast_float::from_chars(c == '+' ? p + 1 : p, end, v, fast_float::chars_format::fixed);
  if (parsed.ec != std::errc()) fail("'" + quoted(p, end) + "' is not a number");
  p = parsed.ptr;
  return v;
}

double NgcExpressionReader::unaryFunction(const std::string& name, const char*& p, const char* end) const {
  skipBlanks(p, end);
  if (name == "exists") {
    if (!(p + 1 < end && p[0] == '[' && p[1] == '#'))
      fail("EXISTS takes a named parameter: EXISTS[#<name>]");
    p += 2;
    std::string parameter;
    if (reference(p, end, parameter) >= 0) fail("EXISTS takes a named parameter: EXISTS[#<name>]");
    skipBlanks(p, end);
    if (p >= end || *p != ']') fail("EXISTS[#<" + parameter + "> is not closed: add ']'");
    ++p;
    return parameters_.exists(parameter) ? 1.0 : 0.0;
  }
  if (p >= end || *p != '[') fail("'" + name + "' is not a function followed by [argument]: is this a " +
                                   (parameters_.macroB() ? "Fanuc macro?" : "LinuxCNC program?"));
  ++p;
  if (parameters_.macroB() && (name == "atan" || name == "pow")) {  // Fanuc 30i: ATAN[y,x], POW[a,b]
    const char* comma = p;
    int depth = 0;
    for (; comma < end && !(depth == 0 && (*comma == ',' || *comma == ']')); ++comma)
      depth += *comma == '[' ? 1 : *comma == ']' ? -1 : 0;
    if (comma < end && *comma == ',') {
      const double a = operations(p, comma, '\0');
      p = comma + 1;
      const double b = orZero(expression(p, end));
      return name == "atan" ? std::atan2(orZero(a), b) / kDegree : apply(static_cast<int>(Op::Power), orZero(a), b);
    }
  }
  const double a = orZero(expression(p, end));
  if (name == "atan") {  // ATAN[y]/[x]
    skipBlanks(p, end);
    if (!(p + 1 < end && p[0] == '/' && p[1] == '[')) fail("ATAN takes two arguments: ATAN[y]/[x]");
    p += 2;
    return std::atan2(a, orZero(expression(p, end))) / kDegree;
  }
  if (parameters_.macroB() && name == "roun") return std::round(a);
  if (name == "abs") return std::abs(a);
  if (name == "acos" || name == "asin") {
    if (a < -1.0 || a > 1.0) fail(name + "[" + number(a) + "]: the argument must be within -1 to 1");
    return (name == "acos" ? std::acos(a) : std::asin(a)) / kDegree;
  }
  if (name == "cos") return std::cos(a * kDegree);
  if (name == "sin") return std::sin(a * kDegree);
  if (name == "tan") return std::tan(a * kDegree);
  if (name == "exp") return std::exp(a);
  if (name == "fix") return std::floor(a);
  if (name == "fup") return std::ceil(a);
  if (name == "round") return std::round(a);  // half away from zero, as rs274ngc
  if (name == "ln") {
    if (a <= 0.0) fail("LN[" + number(a) + "]: the argument must be positive");
    return std::log(a);
  }
  if (name == "sqrt") {
    if (a < 0.0) fail("SQRT[" + number(a) + "]: the argument must not be negative");
    return std::sqrt(a);
  }
  if (parameters_.macroB())
    fail("'" + name + "' is not a Fanuc macro function read here (ABS ACOS ASIN ATAN COS EXP FIX FUP LN POW ROUND SIN SQRT TAN)");
  fail("'" + name + "' is not a LinuxCNC function (ABS ACOS ASIN ATAN COS EXISTS EXP FIX FUP LN ROUND SIN SQRT TAN)");
}

double NgcExpressionReader::apply(int op, double a, double b) const {
  const Op o = static_cast<Op>(op);
  if (o == Op::Eq || o == Op::Ne) {  // Macro B: vacant equals only vacant
    const bool same = NgcParameters::vacant(a) || NgcParameters::vacant(b)
                          ? NgcParameters::vacant(a) && NgcParameters::vacant(b) : a == b;
    return (o == Op::Eq) == same ? 1.0 : 0.0;
  }
  a = orZero(a);
  b = orZero(b);
  switch (o) {
    case Op::Power:
      if (a < 0.0 && std::floor(b) != b) fail("a negative number raised to a non-integer power: check the expression");
      return std::pow(a, b);
    case Op::Times: return a * b;
    case Op::Divide:
      if (b == 0.0) fail("division by zero in an expression");
      return a / b;
    case Op::Modulo: {
      if (b == 0.0) fail("MOD by zero in an expression");
      const double r = std::fmod(a, b);
      return r < 0.0 ? r + std::abs(b) : r;
    }
    case Op::Plus: return a + b;
    case Op::Minus: return a - b;
    case Op::Eq: return a == b ? 1.0 : 0.0;
    case Op::Ne: return a != b ? 1.0 : 0.0;
    case Op::Gt: return a > b ? 1.0 : 0.0;
    case Op::Ge: return a >= b ? 1.0 : 0.0;
    case Op::Lt: return a < b ? 1.0 : 0.0;
    case Op::Le: return a <= b ? 1.0 : 0.0;
    case Op::And: return (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
    case Op::Or: return (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
    default: return ((a != 0.0) != (b != 0.0)) ? 1.0 : 0.0;  // xor
  }
}

double NgcExpressionReader::expression(const char*& p, const char* end) const { return operations(p, end, ']'); }

double NgcExpressionReader::toEnd(const char*& p, const char* end) const { return operations(p, end, '\0'); }

double NgcExpressionReader::operations(const char*& p, const char* end, char closing) const {
  // Operator precedence by two stacks, as rs274ngc's read_real_expression (small: on the stack, no allocation).
  constexpr int kDepth = 8;  // at most one pending operator per precedence level, plus the one read
  double values[kDepth];
  Op ops[kDepth];
  int count = 0;  // pending operators; values has count + 1
  values[0] = value(p, end);
  auto reduce = [&]() {
    --count;
    values[count] = apply(static_cast<int>(ops[count]), values[count], values[count + 1]);
  };
  for (;;) {
    skipBlanks(p, end);
    const bool ends = closing == ']' ? p < end && *p == ']' : p >= end || *p == '(' || *p == ';';
    if (p >= end && closing == ']') fail("'[' is not closed: add ']'");
    if (ends) {
      if (closing == ']') ++p;
      while (count > 0) reduce();
      if (count == 0 && NgcParameters::vacant(values[0]) && parameters_.macroB()) return values[0];  // #1=#0
      if (!std::isfinite(values[0])) fail("an expression's value is not a finite number: check it");
      return values[0];
    }
    Op op = Op::None;
    if (*p == '*' && p + 1 < end && p[1] == '*') {
      op = Op::Power;
      p += 2;
    } else if (*p == '*' || *p == '/' || *p == '+' || *p == '-') {
      op = *p == '*' ? Op::Times : *p == '/' ? Op::Divide : *p == '+' ? Op::Plus : Op::Minus;
      ++p;
    } else if (isLetter(*p)) {
      std::string word;
      while (p < end && isLetter(*p)) word += lower(*p++);
      op = wordOperator(word);
      if (op == Op::None && word[0] == 'e' && (p < end && (isDigit(*p) || *p == '-' || *p == '+')))
        fail("a number with an exponent ('e" + quoted(p, end) + "'): G-code numbers have none; write it in full (1000, not 1e3)");
      if (op == Op::None) fail("'" + word + "' is not an operator (** * / MOD + - EQ NE GT GE LT LE AND OR XOR)");
    } else {
      fail("'" + quoted(p, end) + "' is not an operator: expected one of ** * / MOD + - EQ NE GT GE LT LE AND OR XOR or ']'");
    }
    while (count > 0 && precedence(ops[count - 1]) >= precedence(op)) reduce();
    ops[count++] = op;
    values[count] = value(p, end);
  }
}

// ---------------------------------------------------------------------------------------------------------
// Lines

bool usesParameters(std::string_view raw) {
  return raw.find('#') != std::string_view::npos || raw.find('[') != std::string_view::npos;
}

namespace {
// A unary function as a word's value (X SIN[30]): letters then '['.
bool isFunctionCall(const char* p, const char* end) {
  while (p < end && isLetter(*p)) ++p;
  skipBlanks(p, end);
  return p < end && *p == '[';
}

// With a point always: a computed value is a length in program units, never a count of least increments.
void appendNumber(std::string& out, double v) {
  char buffer[400];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed);
  out.append(buffer, result.ptr);
  if (std::find(buffer, result.ptr, '.') == result.ptr) out += ".0";
}
}  // namespace

std::string_view substituteParameters(std::string_view raw, long line, NgcParameters& parameters, std::string& out) {
  if (!usesParameters(raw)) return raw;
  out.clear();
  struct Setting {
    int number;
    std::string name;
    double value;
  };
  thread_local std::vector<Setting> settings;  // kept between lines: a loop's assignment allocates nothing
  settings.clear();
  const NgcExpressionReader reader(parameters, line);
  const char* p = raw.data();
  const char* end = p + raw.size();
  while (p < end) {
    const char c = *p;
    if (c == ' ' || c == '\t') {
      ++p;
    } else if (c == ';') {
      break;
    } else if (c == '(') {
      p = afterComment(p, end, line);
    } else if (c == '#') {
      Setting s;
      ++p;
      s.number = reader.reference(p, end, s.name);
      skipBlanks(p, end);
      if (p >= end || *p != '=')
        throw ParseError(line, "a parameter stands alone: set it (#1 = ...) or give it as a word's value (X#1)");
      ++p;
      s.value = parameters.macroB() ? reader.toEnd(p, end) : reader.value(p, end);
      settings.push_back(std::move(s));
    } else if (isLetter(c) || c == '%' || c == '/') {
      out += c;
      ++p;
      if (c == '%' || c == '/') continue;
      skipBlanks(p, end);
      const char* digits = p < end && (*p == '-' || *p == '+') ? p + 1 : p;
      if (digits < end && (isDigit(*digits) || *digits == '.')) {  // a literal: as written, for the lexer
        const char* stop = digits;
        while (stop < end && (isDigit(*stop) || *stop == '.')) ++stop;
        out.append(p, stop);
        p = stop;
      } else if (p < end && (!isLetter(*p) || isFunctionCall(p, end))) {
        const double v = reader.value(p, end);
        if (NgcParameters::vacant(v)) {  // Macro B: a word given a vacant value is not in the block
          out.pop_back();
          continue;
        }
        appendNumber(out, v);
      }
      out += ' ';
    } else {
      throw ParseError(line, std::string("unexpected character '") + c + "': G-code words are a letter and a value");
    }
  }
  for (const Setting& s : settings) {
    if (s.number >= 0)
      parameters.setNumbered(s.number, s.value, line);
    else
      parameters.setNamed(s.name, s.value);
  }
  return out;
}

}  // namespace hsm::kinematics::detail
