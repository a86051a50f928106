#include "kinematics/siemens_variables.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace hsm::kinematics::detail {

namespace {
constexpr double kDegree = M_PI / 180.0;
constexpr auto isLetter = isAsciiLetter;
constexpr auto isDigit = isAsciiDigit;
constexpr auto upper = asciiUpper;

void blanks(const char*& p, const char* end) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
}

bool identifierChar(char c) { return isLetter(c) || isDigit(c) || c == '_'; }

std::string identifier(const char*& p, const char* end) {
  const char* start = p;
  while (p < end && identifierChar(*p)) ++p;
  std::string name(start, p);
  for (char& c : name) c = upper(c);
  return name;
}

// R and digits: an R parameter's name (R0 … R999 exist; a longer one is refused where it is set)
bool isRName(const std::string& name) {
  return name.size() >= 2 && name[0] == 'R' && std::all_of(name.begin() + 1, name.end(), [](char c) { return isDigit(c); });
}

bool isRParameter(const std::string& name) { return isRName(name) && name.size() <= 4; }

// A computed value as the lexer reads it back: to the nanometre (9 decimals, trailing zeros dropped) by integer
// arithmetic, several times faster than the shortest exact form, which values beyond 10^8 still get.
void appendValue(std::string& out, double v) {
  char buffer[400];
  if (std::abs(v) < 1e8) {
    const long long scaled = std::llround(std::abs(v) * 1e9);
    long long whole = scaled / 1'000'000'000LL, fraction = scaled % 1'000'000'000LL;
    char* p = buffer + 64;
    char* end = p;
    if (fraction != 0) {
      int digits = 9;
      while (fraction % 10 == 0) {
        fraction /= 10;
        --digits;
      }
      for (int i = 0; i < digits; ++i, fraction /= 10) *--p = static_cast<char>('0' + fraction % 10);
      *--p = '.';
    }
    do {
      *--p = static_cast<char>('0' + whole % 10);
      whole /= 10;
    } while (whole != 0);
    if (v < 0 && scaled != 0) *--p = '-';
    out.append(p, end);
    return;
  }
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed);
  out.append(buffer, result.ptr);
}
}  // namespace

// Recursive descent over the 840D's arithmetic and conditions: either := both {(OR|XOR) both}; both := negation
// {AND negation}; negation := NOT negation | comparison; comparison := sum [(==|<>|<|>|<=|>=) sum]; sum := product
// {(+|-) product}; product := unary {(*|/|DIV|MOD) unary}; unary := [+|-] primary; primary := number | variable |
// (either) | FUNCTION(sum[, sum]).
class SiemensVariables::Reader {
public:
  Reader(const SiemensVariables& variables, long line) : variables_(variables), line_(line) {}

  double either(const char*& p, const char* end) const {
    double value = both(p, end);
    for (std::string op = operatorWord(p, end); op == "OR" || op == "XOR"; op = operatorWord(p, end)) {
      skipWord(p, end);
      const bool right = both(p, end) != 0.0;
      value = op == "OR" ? (value != 0.0 || right) : ((value != 0.0) != right);
    }
    return value;
  }

  double sum(const char*& p, const char* end) const {
    double value = product(p, end);
    for (;;) {
      const char* q = p;
      blanks(q, end);
      if (q < end && (*q == '+' || *q == '-')) {
        const char op = *q++;
        p = q;
        const double right = product(p, end);
        value = op == '+' ? value + right : value - right;
      } else {
        return value;
      }
    }
  }

private:
  [[noreturn]] void fail(const std::string& message) const { throw ParseError(line_, message); }

  // The word of letters at `p` (after blanks), in capitals, without moving `p`.
  static std::string operatorWord(const char* p, const char* end) {
    blanks(p, end);
    std::string word;
    while (p < end && isLetter(*p) && word.size() < 4) word += upper(*p++);
    return (p < end && identifierChar(*p)) ? std::string() : word;
  }
  static void skipWord(const char*& p, const char* end) {
    blanks(p, end);
    while (p < end && isLetter(*p)) ++p;
  }

  double both(const char*& p, const char* end) const {
    double value = negation(p, end);
    while (operatorWord(p, end) == "AND") {
      skipWord(p, end);
      const bool right = negation(p, end) != 0.0;
      value = value != 0.0 && right;
    }
    return value;
  }

  double negation(const char*& p, const char* end) const {
    if (operatorWord(p, end) == "NOT") {
      skipWord(p, end);
      return negation(p, end) == 0.0;
    }
    return comparison(p, end);
  }

  double comparison(const char*& p, const char* end) const {
    const double left = sum(p, end);
    const char* q = p;
    blanks(q, end);
    if (q >= end) return left;
    std::string op;
    if (q + 1 < end && (std::string_view(q, 2) == "==" || std::string_view(q, 2) == "<>" ||
                        std::string_view(q, 2) == "<=" || std::string_view(q, 2) == ">="))
      op.assign(q, 2);
    else if (*q == '<' || *q == '>')
      op.assign(q, 1);
    else
      return left;
    p = q + op.size();
    const double right = sum(p, end);
    if (op == "==") return left == right;
    if (op == "<>") return left != right;
    if (op == "<=") return left <= right;
    if (op == ">=") return left >= right;
    return op == "<" ? left < right : left > right;
  }

  double product(const char*& p, const char* end) const {
    double value = unary(p, end);
    for (;;) {
      const char* q = p;
      blanks(q, end);
      std::string word;
      char op = 0;
      if (q < end && (*q == '*' || *q == '/')) {
        op = *q++;
      } else if (q + 3 <= end && isLetter(*q)) {
        const char* r = q;
        word = identifier(r, end);
        if (word == "DIV" || word == "MOD") {
          op = word[0];
          q = r;
        }
      }
      if (op == 0) return value;
      p = q;
      const double right = unary(p, end);
      if ((op == '/' || op == 'D' || op == 'M') && right == 0.0) fail("division by zero in an expression");
      value = op == '*' ? value * right : op == '/' ? value / right : op == 'D' ? std::trunc(value / right)
                                                                               : std::fmod(value, right);
    }
  }

  double unary(const char*& p, const char* end) const {
    blanks(p, end);
    if (p < end && (*p == '-' || *p == '+')) {
      const char sign = *p++;
      const double v = unary(p, end);
      return sign == '-' ? -v : v;
    }
    return primary(p, end);
  }

  double primary(const char*& p, const char* end) const {
    blanks(p, end);
    if (p >= end) fail("a value is missing at the end of the line");
    if (*p == '(') {
      ++p;
      const double v = either(p, end);
      close(p, end);
      return v;
    }
    if (isDigit(*p) || *p == '.') {
      double v = 0.0;
      const auto parsed = fast_float::from_chars(p, end, v, fast_float::chars_format::fixed);
      if (parsed.ec != std::errc()) fail("'" + std::string(p, std::min<size_t>(end - p, 16)) + "' is not a number");
      p = parsed.ptr;
      if (p < end && (*p == 'E' || *p == 'e') && p + 1 < end && (isDigit(p[1]) || p[1] == '-' || p[1] == '+' || p[1] == 'X'))
        fail("a number with an exponent ('" + std::string(parsed.ptr - 1, std::min<size_t>(end - parsed.ptr + 1, 8)) +
             "'): not read; write the number in full");
      return v;
    }
    if (!isLetter(*p) && *p != '_')
      fail(std::string("unexpected character '") + *p + "' in an expression");
    const std::string name = identifier(p, end);
    const char* q = p;
    blanks(q, end);
    if (q < end && *q == '(') {
      p = q + 1;
      return function(name, p, end);
    }
    return variables_.get(name, line_);
  }

  void close(const char*& p, const char* end) const {
    blanks(p, end);
    if (p >= end || *p != ')') fail("'(' is not closed: add ')'");
    ++p;
  }

  double function(const std::string& name, const char*& p, const char* end) const {
    const double a = sum(p, end);
    blanks(p, end);
    if (name == "ATAN2" || name == "MINVAL" || name == "MAXVAL") {
      if (p >= end || *p != ',') fail(name + " takes two arguments: " + name + "(a, b)");
      ++p;
      const double b = sum(p, end);
      close(p, end);
      return name == "ATAN2" ? std::atan2(a, b) / kDegree : name == "MINVAL" ? std::min(a, b) : std::max(a, b);
    }
    close(p, end);
    if (name == "SIN") return std::sin(a * kDegree);
    if (name == "COS") return std::cos(a * kDegree);
    if (name == "TAN") return std::tan(a * kDegree);
    if (name == "ASIN" || name == "ACOS") {
      if (a < -1.0 || a > 1.0) fail(name + "(" + number(a) + "): the argument must be within -1 to 1");
      return (name == "ASIN" ? std::asin(a) : std::acos(a)) / kDegree;
    }
    if (name == "SQRT") {
      if (a < 0.0) fail("SQRT(" + number(a) + "): the argument must not be negative");
      return std::sqrt(a);
    }
    if (name == "POT") return a * a;
    if (name == "ABS") return std::abs(a);
    if (name == "TRUNC") return std::trunc(a);
    if (name == "ROUND") return std::round(a);
    if (name == "AC") return a;
    if (name == "IC") fail("IC(): an incremental value on one axis is not read yet; program it in G91 or absolute");
    fail("'" + name + "(' is not an 840D function read here (SIN COS TAN ASIN ACOS ATAN2 SQRT POT ABS TRUNC ROUND "
                      "MINVAL MAXVAL AC)");
  }

  const SiemensVariables& variables_;
  long line_;
};

double SiemensVariables::evaluate(const char*& p, const char* end, long line) const {
  return Reader(*this, line).either(p, end);
}

bool SiemensVariables::isVariable(const std::string& name) const {
  return isRParameter(name) || scopes_.back().count(name) > 0;
}

double SiemensVariables::get(const std::string& name, long line) const {
  if (isRParameter(name)) return r_[static_cast<size_t>(std::stoi(name.substr(1)))];
  const auto found = scopes_.back().find(name);
  if (found == scopes_.back().end())
    throw ParseError(line, "'" + name + "' is neither an R parameter nor a variable declared by DEF: declare it "
                                        "(DEF REAL " + name + ") or check its spelling");
  return found->second;
}

void SiemensVariables::set(const std::string& name, double value, long line) {
  if (!std::isfinite(value)) throw ParseError(line, name + " would be set to a value that is not a finite number");
  if (isRParameter(name))
    r_[static_cast<size_t>(std::stoi(name.substr(1)))] = value;
  else
    scopes_.back()[name] = value;
}

void SiemensVariables::declare(const char*& p, const char* end, long line) {
  blanks(p, end);
  const std::string type = identifier(p, end);
  static const char* kTypes[] = {"REAL", "INT", "BOOL", "CHAR", "STRING", "AXIS", "FRAME"};
  if (std::none_of(std::begin(kTypes), std::end(kTypes), [&](const char* t) { return type == t; }))
    throw ParseError(line, "DEF " + type + ": the types read are REAL, INT, BOOL, CHAR, STRING, AXIS and FRAME");
  for (;;) {
    blanks(p, end);
    const std::string name = identifier(p, end);
    if (name.empty()) throw ParseError(line, "DEF " + type + " needs a variable's name");
    if (p < end && *p == '[') throw ParseError(line, "DEF " + name + "[…]: arrays are not read yet");
    double value = 0.0;
    blanks(p, end);
    if (p < end && *p == '=') {
      ++p;
      blanks(p, end);
      if (p < end && *p == '"') {  // a STRING's or CHAR's value: skipped
        const char* close = std::find(p + 1, end, '"');
        p = close < end ? close + 1 : end;
      } else {
        value = Reader(*this, line).sum(p, end);
      }
    }
    scopes_.back()[name] = value;
    blanks(p, end);
    if (p >= end || *p == ';') return;
    if (*p != ',') throw ParseError(line, "DEF: names are separated by commas");
    ++p;
  }
}

bool SiemensVariables::plainAssignments(std::string_view raw) const {
  // Every '=' gives an address (A3=, CR=) a plain number, as posts write them: the lexer reads the line as it is.
  for (size_t at = raw.find('='); at != std::string_view::npos; at = raw.find('=', at + 1)) {
    size_t from = at;
    while (from > 0 && identifierChar(raw[from - 1])) --from;
    std::string name;
    for (size_t i = from; i < at; ++i) name += upper(raw[i]);
    if (name.size() < 2 || isVariable(name) || isRName(name)) return false;  // X=5 is rewritten as the word X5
    size_t p = at + 1;
    if (p < raw.size() && (raw[p] == '-' || raw[p] == '+')) ++p;
    const size_t digits = p;
    while (p < raw.size() && (isDigit(raw[p]) || raw[p] == '.')) ++p;
    if (p == digits || (p < raw.size() && raw[p] != ' ' && raw[p] != '\t' && raw[p] != ';')) return false;
  }
  return true;
}

std::string_view SiemensVariables::substitute(std::string_view raw, long line, std::string& out) {
  const bool declares = raw.find("DEF ") != std::string_view::npos || raw.find("def ") != std::string_view::npos;
  if (!declares && plainAssignments(raw)) return raw;
  out.clear();
  const char* p = raw.data();
  const char* end = p + raw.size();
  while (p < end) {
    const char c = *p;
    if (c == ';') break;
    if (c == '"') {  // a string (MSG("…"), T="name"): as written
      const char* close = std::find(p + 1, end, '"');
      out.append(p, close < end ? close + 1 : end);
      p = close < end ? close + 1 : end;
      continue;
    }
    if (!(isLetter(c) || c == '_')) {
      out += c;
      ++p;
      continue;
    }
    const char* start = p;
    const std::string name = identifier(p, end);
    if (name == "DEF" && (p == end || *p == ' ' || *p == '\t')) {
      declare(p, end, line);
      break;
    }
    const char* q = p;
    blanks(q, end);
    const bool assigns = q < end && *q == '=' && !(q + 1 < end && q[1] == '=');
    if (!assigns) {
      out.append(start, p);
      continue;
    }
    p = q + 1;
    blanks(p, end);
    if (p < end && *p == '"') {  // T="DRILL 8.5": a name, as written
      const char* close = std::find(p + 1, end, '"');
      out.append(start, close < end ? close + 1 : end);
      p = close < end ? close + 1 : end;
      continue;
    }
    {  // `A3= F100`: the value is missing, the next word follows
      const char* r = p;
      const std::string next = identifier(r, end);
      const bool word = next.size() >= 2 && isLetter(next[0]) && std::all_of(next.begin() + 1, next.end(), [](char ch) {
        return isDigit(ch);
      }) && !isVariable(next);
      if (p >= end || *p == ';' || (word && (r >= end || *r != '(')))
        throw ParseError(line, name + "= needs a number, or an expression of R parameters and DEF variables");
    }
    if (isRName(name) && !isRParameter(name))
      throw ParseError(line, name + " is not an R parameter: they are R0 to R" + std::to_string(kSiemensRParameters - 1));
    const double value = Reader(*this, line).sum(p, end);
    if (isVariable(name)) {
      set(name, value, line);  // an assignment to a variable: nothing for the lexer
      continue;
    }
    out += ' ';
    out += name;
    if (name.size() > 1) out += '=';  // CR=, ADIS=, A3=: keywords with a value; X=…: the word X…
    appendValue(out, value);
    out += ' ';
  }
  return out;
}

}  // namespace hsm::kinematics::detail
