#include "kinematics/siemens_variables.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/siemens_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace hsm::kinematics::detail {

namespace {
constexpr auto isLetter = isAsciiLetter;
constexpr auto isDigit = isAsciiDigit;
constexpr auto upper = asciiUpper;

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

double SiemensVariables::evaluate(const char*& p, const char* end, long line) const {
  SiemensExpression e;
  compileSiemensExpression(p, end, line, e);
  return evaluate(e, line);
}

double SiemensVariables::evaluate(const SiemensExpression& e, long line) const {
  return runSiemensExpression(
      e, line, stack_, [this](int index) { return r_[static_cast<size_t>(index)]; },
      [this](const std::string& name, long at) { return get(name, at); });
}

bool SiemensVariables::isVariable(const std::string& name) const {
  return siemens_text::isRParameter(name) || scopes_.back().count(name) > 0;
}

double SiemensVariables::get(const std::string& name, long line) const {
  if (siemens_text::isRParameter(name)) return r_[static_cast<size_t>(std::stoi(name.substr(1)))];
  const auto found = scopes_.back().find(name);
  if (found == scopes_.back().end())
    throw ParseError(line, "'" + name + "' is neither an R parameter nor a variable declared by DEF: declare it "
                                        "(DEF REAL " + name + ") or check its spelling");
  return found->second;
}

void SiemensVariables::set(const std::string& name, double value, long line) {
  if (!std::isfinite(value)) throw ParseError(line, name + " would be set to a value that is not a finite number");
  if (siemens_text::isRParameter(name))
    r_[static_cast<size_t>(std::stoi(name.substr(1)))] = value;
  else
    scopes_.back()[name] = value;
}

void SiemensVariables::compileDeclaration(const char*& p, const char* end, long line, SiemensLine& out) const {
  skipBlanks(p, end);
  const std::string type = siemens_text::name(p, end);
  static const char* kTypes[] = {"REAL", "INT", "BOOL", "CHAR", "STRING", "AXIS", "FRAME"};
  if (std::none_of(std::begin(kTypes), std::end(kTypes), [&](const char* t) { return type == t; }))
    throw ParseError(line, "DEF " + type + ": the types read are REAL, INT, BOOL, CHAR, STRING, AXIS and FRAME");
  for (;;) {
    skipBlanks(p, end);
    SiemensLine::Piece piece;
    piece.kind = SiemensLine::Piece::Declare;
    piece.text = siemens_text::name(p, end);
    piece.hasValue = false;
    if (piece.text.empty()) throw ParseError(line, "DEF " + type + " needs a variable's name");
    if (p < end && *p == '[') throw ParseError(line, "DEF " + piece.text + "[...]: arrays are not read yet");
    skipBlanks(p, end);
    if (p < end && *p == '=') {
      ++p;
      skipBlanks(p, end);
      if (p < end && *p == '"') {  // a STRING's or CHAR's value: skipped
        const char* close = std::find(p + 1, end, '"');
        p = close < end ? close + 1 : end;
      } else {
        compileSiemensExpression(p, end, line, piece.value);
        piece.hasValue = true;
      }
    }
    out.pieces.push_back(std::move(piece));
    skipBlanks(p, end);
    if (p >= end || *p == ';') return;
    if (*p != ',') throw ParseError(line, "DEF: names are separated by commas");
    ++p;
  }
}

bool SiemensVariables::plainAssignments(std::string_view raw) const {
  // Every '=' gives an address (A3=, CR=) a plain number, as posts write them: the lexer reads the line as it is.
  for (size_t at = raw.find('='); at != std::string_view::npos; at = raw.find('=', at + 1)) {
    size_t from = at;
    while (from > 0 && siemens_text::nameChar(raw[from - 1])) --from;
    std::string name;
    for (size_t i = from; i < at; ++i) name += upper(raw[i]);
    if (name.size() < 2 || isVariable(name) || siemens_text::isRName(name)) return false;  // X=5 is rewritten as the word X5
    size_t p = at + 1;
    if (p < raw.size() && (raw[p] == '-' || raw[p] == '+')) ++p;
    const size_t digits = p;
    while (p < raw.size() && (isDigit(raw[p]) || raw[p] == '.')) ++p;
    if (p == digits || (p < raw.size() && raw[p] != ' ' && raw[p] != '\t' && raw[p] != ';')) return false;
  }
  return true;
}

std::string_view SiemensVariables::substitute(std::string_view raw, long line, std::string& out) {
  SiemensLine compiled;
  compile(raw, line, compiled);
  return run(compiled, raw, line, out);
}

void SiemensVariables::compile(std::string_view raw, long line, SiemensLine& out) const {
  out.pieces.clear();
  const bool declares = raw.find("DEF ") != std::string_view::npos || raw.find("def ") != std::string_view::npos;
  out.asWritten = !declares && plainAssignments(raw);
  if (out.asWritten) return;
  auto text = [&](const char* from, const char* to) {
    if (out.pieces.empty() || out.pieces.back().kind != SiemensLine::Piece::Text) out.pieces.emplace_back();
    out.pieces.back().text.append(from, to);
  };
  const char* p = raw.data();
  const char* end = p + raw.size();
  while (p < end) {
    const char c = *p;
    if (c == ';') break;
    if (c == '"') {  // a string (MSG("..."), T="name"): as written
      const char* close = std::find(p + 1, end, '"');
      text(p, close < end ? close + 1 : end);
      p = close < end ? close + 1 : end;
      continue;
    }
    if (!(isLetter(c) || c == '_')) {
      text(p, p + 1);
      ++p;
      continue;
    }
    const char* start = p;
    const std::string name = siemens_text::name(p, end);
    if (name == "DEF" && (p == end || *p == ' ' || *p == '\t')) {
      compileDeclaration(p, end, line, out);
      break;
    }
    const char* q = p;
    skipBlanks(q, end);
    const bool assigns = q < end && *q == '=' && !(q + 1 < end && q[1] == '=');
    if (!assigns) {
      text(start, p);
      continue;
    }
    p = q + 1;
    skipBlanks(p, end);
    if (p < end && *p == '"') {  // T="DRILL 8.5": a name, as written
      const char* close = std::find(p + 1, end, '"');
      text(start, close < end ? close + 1 : end);
      p = close < end ? close + 1 : end;
      continue;
    }
    {  // `A3= F100`: the value is missing, the next word follows
      const char* r = p;
      const std::string next = siemens_text::name(r, end);
      const bool word = next.size() >= 2 && isLetter(next[0]) && std::all_of(next.begin() + 1, next.end(), [](char ch) {
        return isAsciiDigit(ch);
      }) && !isVariable(next);
      if (p >= end || *p == ';' || (word && (r >= end || *r != '(')))
        throw ParseError(line, name + "= needs a number, or an expression of R parameters and DEF variables");
    }
    if (siemens_text::isRName(name) && !siemens_text::isRParameter(name))
      throw ParseError(line, name + " is not an R parameter: they are R0 to R" + std::to_string(kSiemensRParameters - 1));
    SiemensLine::Piece piece;
    piece.kind = isVariable(name) ? SiemensLine::Piece::Assign : SiemensLine::Piece::Address;
    piece.text = name;
    const bool axis = name.size() == 1 && std::string_view("XYZABC").find(name[0]) != std::string_view::npos;
    if (axis && p + 2 < end && (upper(p[0]) == 'I' || upper(p[0]) == 'A') && upper(p[1]) == 'C' && p[2] == '(') {
      // X=IC(…) / X=AC(…): this axis incremental / absolute on this block (the word ICX= / ACX= for the lexer)
      piece.text = std::string(1, upper(p[0])) + "C" + name;
      p += 3;
      compileSiemensExpression(p, end, line, piece.value);
      skipBlanks(p, end);
      if (p >= end || *p != ')') throw ParseError(line, name + "=" + piece.text.substr(0, 2) + "(: ')' is missing");
      ++p;
    } else {
      compileSiemensExpression(p, end, line, piece.value);
    }
    out.pieces.push_back(std::move(piece));
  }
}

std::string_view SiemensVariables::run(const SiemensLine& compiled, std::string_view raw, long line, std::string& out) {
  if (compiled.asWritten) return raw;
  out.clear();
  for (const SiemensLine::Piece& piece : compiled.pieces) {
    switch (piece.kind) {
      case SiemensLine::Piece::Text: out += piece.text; break;
      case SiemensLine::Piece::Declare: scopes_.back()[piece.text] = piece.hasValue ? evaluate(piece.value, line) : 0.0; break;
      case SiemensLine::Piece::Assign: set(piece.text, evaluate(piece.value, line), line); break;
      case SiemensLine::Piece::Address:
        out += ' ';
        out += piece.text;
        if (piece.text.size() > 1) out += '=';  // CR=, ADIS=, A3=: keywords with a value; X=...: the word X...
        appendValue(out, evaluate(piece.value, line));
        out += ' ';
        break;
    }
  }
  return out;
}

}  // namespace hsm::kinematics::detail
