// Reading the 840D's statements (internal, for siemens_program*.cpp): names, arguments in parentheses, the
// statement's keyword.
#pragma once

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/ngc_expression.hpp"
#include "kinematics/gcode.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics::detail::siemens_text {

using namespace std::string_view_literals;

inline bool nameStart(char c) { return isAsciiLetter(c) || c == '_'; }
inline bool nameChar(char c) { return isAsciiLetter(c) || isAsciiDigit(c) || c == '_'; }

inline std::string name(const char*& p, const char* end) {
  const char* start = p;
  while (p < end && nameChar(*p)) ++p;
  std::string word(start, p);
  for (char& c : word) c = asciiUpper(c);
  return word;
}

inline std::string capitals(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = asciiUpper(c);
  return out;
}

// The statement's keyword: a name of two letters (or underscores) or more, or L and digits (a subprogram);
// empty for a block of address words (G1 X10 …).
inline std::string keywordOf(std::string_view statement) {
  if (statement.size() < 2 || !nameStart(statement[0])) return {};
  const bool lNumber = (statement[0] == 'L' || statement[0] == 'l') && isAsciiDigit(statement[1]);
  if (!nameStart(statement[1]) && !lNumber) return {};
  const char* p = statement.data();
  return name(p, p + statement.size());
}

inline bool endOfStatement(const char* p, const char* end) {
  skipBlanks(p, end);
  return p >= end || *p == ';';
}

// The statement's arguments in parentheses from `p` (at its '('), without them; `p` is left after the ')'.
inline std::string_view parenthesised(const char*& p, const char* end, long line) {
  const char* open = p;
  int depth = 0;
  for (; p < end; ++p) {
    if (*p == '"') {
      const char* close = std::find(p + 1, end, '"');
      p = close < end ? close : end - 1;
    } else if (*p == '(') {
      ++depth;
    } else if (*p == ')' && --depth == 0) {
      ++p;
      return std::string_view(open + 1, static_cast<size_t>(p - open - 2));
    }
  }
  throw ParseError(line, "'(' is not closed: add ')'");
}

// The comma-separated parts of an argument list (commas inside parentheses and strings do not count).
inline std::vector<std::string_view> commaParts(std::string_view list) {
  std::vector<std::string_view> parts;
  size_t from = 0;
  int depth = 0;
  for (size_t i = 0; i < list.size(); ++i) {
    const char c = list[i];
    if (c == '"') {
      const size_t close = list.find('"', i + 1);
      i = close == std::string_view::npos ? list.size() - 1 : close;
    } else if (c == '(') {
      ++depth;
    } else if (c == ')') {
      --depth;
    } else if (c == ',' && depth == 0) {
      parts.push_back(list.substr(from, i - from));
      from = i + 1;
    }
  }
  if (!list.empty()) parts.push_back(list.substr(from));
  return parts;
}

inline std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// PROC NAME(REAL A, VAR INT B, STRING[32] C …): the parameters' names, in order.
// The first letters of the 840D's standard cycles that the simulator does not model (measuring, milling and
// pattern cycles): the interpreter names them as motion it cannot see.
inline bool isStandardCycle(const std::string& word) {
  for (const char* prefix : {"CYCLE", "POCKET", "SLOT", "HOLES"}) {
    const size_t length = std::char_traits<char>::length(prefix);
    if (word.size() > length && word.compare(0, length, prefix) == 0 &&
        std::all_of(word.begin() + static_cast<std::ptrdiff_t>(length), word.end(), [](char c) { return isAsciiDigit(c); }))
      return true;
  }
  return word == "LONGHOLE"sv;
}

// PROC NAME(REAL A, VAR INT B, STRING[32] C ...): the parameters' names, in order.
inline std::vector<std::string> procParameters(const char* p, const char* end, long line) {
  skipBlanks(p, end);
  name(p, end);
  skipBlanks(p, end);
  std::vector<std::string> names;
  if (p >= end || *p != '(') return names;
  for (std::string_view part : commaParts(parenthesised(p, end, line))) {
    part = trimmed(part);
    const char* q = part.data();
    const char* e = q + part.size();
    std::string word = name(q, e);
    if (word == "VAR"sv) {
      skipBlanks(q, e);
      word = name(q, e);
    }
    if (q < e && *q == '[') q = std::find(q, e, ']') + (q < e ? 1 : 0);  // STRING[32]
    skipBlanks(q, e);
    const std::string parameter = name(q, e);
    if (parameter.empty()) throw ParseError(line, "PROC: a parameter is written as its type and name (REAL DEPTH)");
    names.push_back(parameter);
  }
  return names;
}

// R and digits: an R parameter's name (R0 … R999 exist; a longer one is refused where it is set)
inline bool isRName(const std::string& name) {
  return name.size() >= 2 && name[0] == 'R' &&
         std::all_of(name.begin() + 1, name.end(), [](char c) { return isAsciiDigit(c); });
}

inline bool isRParameter(const std::string& name) { return isRName(name) && name.size() <= 4; }

}  // namespace hsm::kinematics::detail::siemens_text
