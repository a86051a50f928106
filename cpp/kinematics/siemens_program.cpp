#include "kinematics/siemens_program.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/gcode_interpreter.hpp"
#include "kinematics/ngc_program.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace hsm::kinematics::detail {

using namespace std::string_view_literals;

namespace {
constexpr auto isDigit = isAsciiDigit;
constexpr auto isLetter = isAsciiLetter;
constexpr auto upper = asciiUpper;
constexpr size_t kProcLines = 200;  // a subprogram file's PROC line is among its first lines (after its header)

bool nameStart(char c) { return isLetter(c) || c == '_'; }
bool nameChar(char c) { return isLetter(c) || isDigit(c) || c == '_'; }

std::string name(const char*& p, const char* end) {
  const char* start = p;
  while (p < end && nameChar(*p)) ++p;
  std::string word(start, p);
  for (char& c : word) c = upper(c);
  return word;
}

std::string capitals(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = upper(c);
  return out;
}

// The statement's keyword: a name of two letters (or underscores) or more, or L and digits (a subprogram);
// empty for a block of address words (G1 X10 …).
std::string keywordOf(std::string_view statement) {
  if (statement.size() < 2 || !nameStart(statement[0])) return {};
  const bool lNumber = (statement[0] == 'L' || statement[0] == 'l') && isDigit(statement[1]);
  if (!nameStart(statement[1]) && !lNumber) return {};
  const char* p = statement.data();
  return name(p, p + statement.size());
}

bool endOfStatement(const char* p, const char* end) {
  skipBlanks(p, end);
  return p >= end || *p == ';';
}

// The statement's arguments in parentheses from `p` (at its '('), without them; `p` is left after the ')'.
std::string_view parenthesised(const char*& p, const char* end, long line) {
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
std::vector<std::string_view> commaParts(std::string_view list) {
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

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// PROC NAME(REAL A, VAR INT B, STRING[32] C …): the parameters' names, in order.
std::vector<std::string> procParameters(const char* p, const char* end, long line) {
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

// An M2, M17 or M30 in the line's words (the program's or subprogram's end), outside strings and comments.
bool endsProgram(std::string_view text) {
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ';') return false;
    if (c == '"') {
      const size_t close = text.find('"', i + 1);
      if (close == std::string_view::npos) return false;
      i = close;
      continue;
    }
    if ((c != 'M' && c != 'm') || (i > 0 && nameChar(text[i - 1])) || i + 1 >= text.size() || !isDigit(text[i + 1]))
      continue;
    long value = 0;
    size_t j = i + 1;
    for (; j < text.size() && isDigit(text[j]) && value < 1000; ++j) value = value * 10 + (text[j] - '0');
    if ((j == text.size() || !(nameChar(text[j]) || text[j] == '.' || text[j] == '(')) &&
        (value == 2 || value == 17 || value == 30))
      return true;
  }
  return false;
}

// Whether the statement is address words only (X1.5 Y2 C30 D1 F100): no assignment, name (a variable, a cycle,
// DEF) or M word (a program's end) to look at.
bool addressWordsOnly(std::string_view statement) {
  // Each character's class: 0 other, 1 a letter or '_' (two in a row make a name), 2 what needs a look
  static const auto kClass = [] {
    std::array<unsigned char, 256> table{};
    for (int c = 0; c < 256; ++c) table[static_cast<size_t>(c)] = nameStart(static_cast<char>(c)) ? 1 : 0;
    for (unsigned char c : {'=', '"', 'M', 'm'}) table[c] = 2;
    table[static_cast<unsigned char>(';')] = 3;
    return table;
  }();
  unsigned char previous = 0;
  for (const char c : statement) {
    const unsigned char k = kClass[static_cast<unsigned char>(c)];
    if (k >= 2) return k == 3;
    if (k & previous) return false;
    previous = k;
  }
  return true;
}

// The first letters of the 840D's standard cycles that the simulator does not model (measuring, milling and
// pattern cycles): the interpreter names them as motion it cannot see.
bool isStandardCycle(const std::string& word) {
  for (const char* prefix : {"CYCLE", "POCKET", "SLOT", "HOLES"}) {
    const size_t length = std::char_traits<char>::length(prefix);
    if (word.size() > length && word.compare(0, length, prefix) == 0 &&
        std::all_of(word.begin() + static_cast<std::ptrdiff_t>(length), word.end(), [](char c) { return isAsciiDigit(c); }))
      return true;
  }
  return word == "LONGHOLE"sv;
}
}  // namespace

SiemensProgram::SiemensProgram(LineSource& source, SiemensOptions options)
    : options_(std::move(options)), files_(source) {
  frames_.emplace_back();
}

void SiemensProgram::fail(long line, const std::string& message) const { throw ParseError(line, message); }

SiemensProgram::Body SiemensProgram::body(std::string_view text) {
  const char* p = text.data();
  const char* end = p + text.size();
  skipBlanks(p, end);
  if (p < end && *p == '/') {  // block delete (skip level /0 … /9): the block runs, as with the switch off
    ++p;
    if (p < end && isDigit(*p)) ++p;
  }
  Body b;
  for (int part = 0; part < 3; ++part) {
    skipBlanks(p, end);
    if (p + 1 < end && (*p == 'N' || *p == 'n' || *p == ':') && isDigit(p[1])) {
      long sequence = 0;
      for (++p; p < end && isDigit(*p); ++p) sequence = std::min(sequence * 10 + (*p - '0'), 999'999'999L);
      b.sequence = sequence;
      continue;
    }
    if (p + 1 < end && nameStart(*p) && nameStart(p[1])) {
      const char* q = p;
      while (q < end && nameChar(*q)) ++q;
      if (q < end && *q == ':') {
        b.label = std::string_view(p, static_cast<size_t>(q - p));
        p = q + 1;
        continue;
      }
    }
    break;
  }
  b.statement = std::string_view(p, static_cast<size_t>(end - p));
  return b;
}

SiemensProgram::CompiledLine& SiemensProgram::compiled(KeptLine& line) {
  if (line.compiled < 0) {
    line.compiled = static_cast<int>(compiled_.size());
    compiled_.emplace_back();
  }
  return compiled_[static_cast<size_t>(line.compiled)];
}

bool SiemensProgram::condition(KeptLine& line, const char*& p, const char* end, long n) {
  CompiledLine& c = compiled(line);
  if (!c.hasCondition) {
    if (endOfStatement(p, end)) fail(n, "IF / WHILE / UNTIL needs a condition (IF R1>5 GOTOF LABEL)");
    const char* q = p;
    compileSiemensExpression(q, end, n, c.condition);
    c.conditionLength = static_cast<size_t>(q - p);
    c.hasCondition = true;
  }
  p += c.conditionLength;
  return variables_.evaluate(c.condition, n) != 0.0;
}

LineCursor SiemensProgram::find(const std::string& target, Direction direction, LineCursor from, long n,
                                                 bool required) {
  const auto key = std::make_tuple(from.file, from.index, target, static_cast<int>(direction));
  const auto known = jumps_.find(key);
  if (known != jumps_.end()) return LineCursor{from.file, known->second};
  const bool blockNumber = target.size() > 1 && target[0] == 'N' &&
                           std::all_of(target.begin() + 1, target.end(), [](char c) { return isAsciiDigit(c); });
  const long wanted = blockNumber ? std::stol(target.substr(1, 9)) : -1;
  auto matches = [&](const KeptLine& line) {
    const Body b = body(line.text);
    if (blockNumber) return b.sequence == wanted;
    if (b.label.size() != target.size()) return false;
    for (size_t i = 0; i < target.size(); ++i)
      if (upper(b.label[i]) != target[i]) return false;
    return true;
  };
  auto forwardSearch = [&](LineCursor& found) {
    LineCursor at = forward(from);
    for (size_t looked = 0; looked < kMaxKeptLines; ++looked, at = forward(at)) {
      const KeptLine* line = files_.fetch(at);
      if (line == nullptr) return false;
      if (matches(*line)) {
        found = at;
        return true;
      }
    }
    return false;
  };
  auto backwardSearch = [&](LineCursor& found) {
    for (size_t i = from.index; i-- > files_[from.file].dropped;) {
      const LineCursor at{from.file, i};
      if (matches(*files_.fetch(at))) {
        found = at;
        return true;
      }
    }
    return false;
  };
  LineCursor found = from;
  bool ok = false;
  if (direction == Direction::Forward) ok = forwardSearch(found);
  else if (direction == Direction::Backward) ok = backwardSearch(found);
  else if (direction == Direction::Both) ok = forwardSearch(found) || backwardSearch(found);
  else ok = backwardSearch(found) || forwardSearch(found);
  if (!ok) {
    if (!required) return from;
    const char* where = direction == Direction::Forward ? "after" : direction == Direction::Backward ? "before" : "in";
    fail(n, std::string(blockNumber ? "block " : "label ") + target + " is not " + where +
                " this line of the program" + (blockNumber ? "" : " (a label is a name and ':' at a block's start)"));
  }
  jumps_[key] = found.index;
  return found;
}

LineCursor SiemensProgram::closing(LineCursor opening, const char* closer, bool elseToo, long n) {
  const auto key = std::make_pair(opening.file, opening.index * 2 + (elseToo ? 1 : 0));
  const auto known = closings_.find(key);
  if (known != closings_.end()) return LineCursor{opening.file, known->second};
  int depth = 0;
  LineCursor at = forward(opening);
  for (size_t looked = 0; looked < kMaxKeptLines; ++looked, at = forward(at)) {
    const KeptLine* line = files_.fetch(at);
    if (line == nullptr) break;
    const std::string_view statement = body(line->text).statement;
    const std::string keyword = keywordOf(statement);
    if (keyword.empty()) continue;
    const bool closes = keyword == "ENDIF"sv || keyword == "ENDWHILE"sv || keyword == "ENDFOR"sv || keyword == "ENDLOOP"sv ||
                        keyword == "UNTIL"sv;
    if (depth == 0 && (keyword == closer || (elseToo && keyword == "ELSE"sv))) {
      closings_[key] = at.index;
      return at;
    }
    const char* rest = statement.data() + keyword.size();
    const char* end = statement.data() + statement.size();
    const bool opens = keyword == "WHILE"sv || keyword == "FOR"sv || keyword == "LOOP"sv ||
                       (keyword == "IF"sv && capitals(statement).find("GOTO") == std::string::npos) ||
                       (keyword == "REPEAT"sv && endOfStatement(rest, end));
    if (opens) ++depth;
    if (closes) --depth;
  }
  const std::string opener = keywordOf(body(files_.fetch(opening)->text).statement);
  fail(n, opener + " has no " + closer + " before its program ends: add it");
}

void SiemensProgram::jump(LineCursor to, long n) {
  if (to.index < files_[to.file].dropped)
    fail(n, "the jump goes back more than " + std::to_string(kKeptBehind) +
                " lines, which are no longer kept (a program this long is drip-fed: the control cannot either)");
  if (to.file == cursor_.file && to.index < cursor_.index && ++jumpsBack_[{to.file, to.index}] > options_.maxLoopIterations)
    fail(n, "the program has jumped back to the same line " + std::to_string(options_.maxLoopIterations) +
                " times: an endless loop? Check the condition of its GOTOB");
  // Structures the jump leaves are left behind (a GOTOF out of a LOOP is how a LOOP ends).
  auto& structures = frames_.back().structures;
  while (!structures.empty()) {
    const Structure& s = structures.back();
    bool inside;
    if (s.kind == Kind::Section) {
      inside = to.index >= s.opening.index && to.index < s.stop.index;
    } else {
      static const std::map<Kind, const char*> kClosers = {{Kind::If, "ENDIF"}, {Kind::While, "ENDWHILE"},
                                                           {Kind::For, "ENDFOR"}, {Kind::Loop, "ENDLOOP"},
                                                           {Kind::Repeat, "UNTIL"}};
      inside = to.index > s.opening.index && to.index <= closing(s.opening, kClosers.at(s.kind), false, n).index;
    }
    if (inside) break;
    structures.pop_back();
  }
  cursor_ = to;
}

void SiemensProgram::loopBack(Structure& s, LineCursor to, const char* what, long n) {
  if (++s.turns > options_.maxLoopIterations)
    fail(n, std::string(what) + " has turned " + std::to_string(options_.maxLoopIterations) +
                " times: an endless loop? Check its condition");
  cursor_ = to;
}

bool SiemensProgram::endOfSection() {
  auto& structures = frames_.back().structures;
  if (structures.empty() || structures.back().kind != Kind::Section || cursor_ != structures.back().stop) return false;
  Structure& s = structures.back();
  if (--s.remaining > 0) {
    cursor_ = s.opening;
  } else {
    cursor_ = s.returnTo;
    structures.pop_back();
  }
  return true;
}

bool SiemensProgram::flowStatement(const std::string& keyword, std::string_view statement, long n, KeptLine& line) {
  const char* p = statement.data() + keyword.size();
  const char* end = statement.data() + statement.size();
  const LineCursor here{cursor_.file, cursor_.index - 1};
  auto& structures = frames_.back().structures;
  auto top = [&](Kind kind, const char* what) -> Structure& {
    if (structures.empty() || structures.back().kind != kind) fail(n, std::string(what) + " without its opening statement");
    return structures.back();
  };
  auto target = [&]() {
    skipBlanks(p, end);
    const std::string label = name(p, end);
    if (label.empty()) fail(n, keyword + " needs the label (or block number N123) to go to");
    return label;
  };
  auto goTo = [&](const std::string& how, const std::string& label) {
    if (how == "GOTOF"sv) jump(find(label, Direction::Forward, here, n), n);
    else if (how == "GOTOB"sv) jump(find(label, Direction::Backward, here, n), n);
    else if (how == "GOTO"sv) jump(find(label, Direction::Both, here, n), n);
    else if (how == "GOTOC"sv) {  // GOTO without the alarm when the label is missing
      const LineCursor to = find(label, Direction::Both, here, n, false);
      if (to != here) jump(to, n);
    }
    else fail(n, how + ": the jumps are GOTOF, GOTOB, GOTO and GOTOC");
  };
  if (keyword == "PROC"sv) {
    if (frames_.size() == 1) {
      const std::vector<std::string> parameters = procParameters(p, end, n);
      if (!parameters.empty()) {
        std::string list;
        for (const std::string& parameter : parameters) list += (list.empty() ? "" : ", ") + parameter;
        const char* q = p;
        skipBlanks(q, end);
        const std::string procName = name(q, end);
        fail(n, "this is subprogram " + procName + ", whose parameters (" + list + ") a caller gives: simulate the "
                "program that calls it (" + procName + "(...)), with this file's folder among the subprogram folders");
      }
    }
    return true;
  }
  if (keyword == "EXTERN"sv) return true;
  if (keyword == "GOTOF"sv || keyword == "GOTOB"sv || keyword == "GOTO"sv || keyword == "GOTOC"sv) {
    goTo(keyword, target());
    return true;
  }
  if (keyword == "GOTOS"sv) {  // back to the program's start: a production loop; one pass is what is timed
    ended_ = true;
    return true;
  }
  if (keyword == "IF"sv) {
    const bool holds = condition(line, p, end, n);
    skipBlanks(p, end);
    const std::string then = name(p, end);
    if (then.rfind("GOTO", 0) == 0) {
      const std::string label = target();
      if (holds) goTo(then, label);
    } else if (then.empty() && endOfStatement(p, end)) {
      if (holds) {
        structures.push_back(Structure{Kind::If, here, {}, {}, {}, 0.0, 0, 0});
      } else {
        const LineCursor other = closing(here, "ENDIF", true, n);
        if (keywordOf(body(files_.fetch(other)->text).statement) == "ELSE")
          structures.push_back(Structure{Kind::If, here, {}, {}, {}, 0.0, 0, 0});
        cursor_ = forward(other);
      }
    } else {
      fail(n, "IF <condition> is followed by GOTOF / GOTOB / GOTO <label>, or stands alone before its blocks and ENDIF");
    }
    return true;
  }
  if (keyword == "ELSE"sv) {
    const LineCursor opening = top(Kind::If, "ELSE").opening;
    cursor_ = forward(closing(opening, "ENDIF", false, n));
    structures.pop_back();
    return true;
  }
  if (keyword == "ENDIF"sv) {
    top(Kind::If, "ENDIF");
    structures.pop_back();
    return true;
  }
  if (keyword == "WHILE"sv) {
    const bool holds = condition(line, p, end, n);
    const bool again = !structures.empty() && structures.back().kind == Kind::While && structures.back().opening == here;
    if (holds && !again) structures.push_back(Structure{Kind::While, here, {}, {}, {}, 0.0, 0, 0});
    if (!holds) {
      if (again) structures.pop_back();
      cursor_ = forward(closing(here, "ENDWHILE", false, n));
    }
    return true;
  }
  if (keyword == "ENDWHILE"sv) {
    Structure& s = top(Kind::While, "ENDWHILE");
    loopBack(s, s.opening, "WHILE ... ENDWHILE", n);
    return true;
  }
  if (keyword == "FOR"sv) {
    skipBlanks(p, end);
    const std::string counter = name(p, end);
    skipBlanks(p, end);
    if (counter.empty() || p >= end || *p != '=') fail(n, "FOR is written FOR <counter> = <start> TO <end>");
    ++p;
    const double first = variables_.evaluate(p, end, n);
    skipBlanks(p, end);
    if (name(p, end) != "TO") fail(n, "FOR " + counter + " = " + number(first) + " needs TO <end value>");
    const double last = variables_.evaluate(p, end, n);
    if (!variables_.isVariable(counter))
      fail(n, "FOR " + counter + ": the counter is an R parameter or a variable declared by DEF INT or DEF REAL");
    variables_.set(counter, first, n);
    if (first > last) cursor_ = forward(closing(here, "ENDFOR", false, n));
    else structures.push_back(Structure{Kind::For, here, {}, {}, counter, last, 0, 0});
    return true;
  }
  if (keyword == "ENDFOR"sv) {
    Structure& s = top(Kind::For, "ENDFOR");
    const double value = variables_.get(s.variable, n) + 1.0;
    variables_.set(s.variable, value, n);
    if (value <= s.last) loopBack(s, forward(s.opening), "FOR ... ENDFOR", n);
    else structures.pop_back();
    return true;
  }
  if (keyword == "LOOP"sv) {
    structures.push_back(Structure{Kind::Loop, here, {}, {}, {}, 0.0, 0, 0});
    return true;
  }
  if (keyword == "ENDLOOP"sv) {
    Structure& s = top(Kind::Loop, "ENDLOOP");
    loopBack(s, forward(s.opening), "LOOP ... ENDLOOP (left only by a jump)", n);
    return true;
  }
  if (keyword == "UNTIL"sv) {
    Structure& s = top(Kind::Repeat, "UNTIL");
    if (condition(line, p, end, n)) structures.pop_back();
    else loopBack(s, forward(s.opening), "REPEAT ... UNTIL", n);
    return true;
  }
  if (keyword == "REPEAT"sv || keyword == "REPEATB"sv) {
    if (keyword == "REPEAT"sv && endOfStatement(p, end)) {
      structures.push_back(Structure{Kind::Repeat, here, {}, {}, {}, 0.0, 0, 0});
      return true;
    }
    const std::string first = target();
    skipBlanks(p, end);
    std::string second;
    const char* q = p;
    const std::string word = name(q, end);
    skipBlanks(q, end);
    const bool passesWord = word == "P"sv && q < end && (*q == '=' || isDigit(*q));
    if (!word.empty() && !passesWord) {
      second = word;
      p = q;
    }
    double passes = 1.0;
    skipBlanks(p, end);
    if (p < end && (*p == 'P' || *p == 'p')) {
      ++p;
      skipBlanks(p, end);
      if (p < end && *p == '=') ++p;
      passes = variables_.evaluate(p, end, n);
    }
    if (!endOfStatement(p, end)) fail(n, keyword + " is written " + keyword + " <label> [<end label>] [P=<passes>]");
    if (!(passes >= 0 && passes == std::floor(passes) && passes <= static_cast<double>(options_.maxLoopIterations)))
      fail(n, keyword + " P=" + number(passes) + ": the passes are a whole number from 0 to " +
                  std::to_string(options_.maxLoopIterations));
    if (passes == 0) return true;
    Structure s{Kind::Section, {}, {}, cursor_, {}, 0.0, 0, static_cast<long>(passes)};
    if (keyword == "REPEATB"sv) {  // the one block with the label
      s.opening = find(first, Direction::BackwardFirst, here, n);
      s.stop = forward(s.opening);
    } else if (second.empty()) {  // from the label back there to this line
      s.opening = find(first, Direction::Backward, here, n);
      s.stop = here;
    } else {  // from the first label to the second, wherever they are
      s.opening = find(first, Direction::BackwardFirst, here, n);
      s.stop = forward(find(second, Direction::Forward, s.opening, n));
    }
    structures.push_back(std::move(s));
    cursor_ = structures.back().opening;
    return true;
  }
  if (keyword == "RET"sv) {
    if (frames_.size() > 1) leave();
    else ended_ = true;
    return true;
  }
  if (keyword == "CALL"sv || keyword == "PCALL"sv) {
    skipBlanks(p, end);
    if (p >= end || *p != '"') fail(n, keyword + " is followed by the program's name in quotes: CALL \"NAME\"");
    const char* close = std::find(p + 1, end, '"');
    std::string_view quoted(p + 1, static_cast<size_t>(std::max<std::ptrdiff_t>(0, close - p - 1)));
    const size_t slash = quoted.find_last_of('/');
    if (slash != std::string_view::npos) quoted.remove_prefix(slash + 1);
    std::string called = capitals(quoted);
    for (const char* suffix : {"_SPF", "_MPF", ".SPF", ".MPF"})
      if (called.size() > 4 && called.compare(called.size() - 4, 4, suffix) == 0) called.resize(called.size() - 4);
    if (called.rfind("_N_", 0) == 0) called.erase(0, 3);
    const Subprogram* found = subprogram(called, n);
    if (found != nullptr) call(*found, called, {}, 1, n);
    return true;
  }
  if (keyword == "MCALL"sv) {
    skipBlanks(p, end);
    const std::string called = name(p, end);
    if (!called.empty() && !isStandardCycle(called))
      fail(n, "MCALL " + called + ": a modal call of a subprogram is not read (read: MCALL CYCLE81 ... CYCLE89)");
  }
  return false;
}

const SiemensProgram::Subprogram* SiemensProgram::subprogram(const std::string& called, long n, bool required) {
  const auto known = subprograms_.find(called);
  if (known != subprograms_.end()) return &known->second;
  auto missing = missing_.find(called);
  if (missing == missing_.end()) {
    std::string lower = called;
    for (char& c : lower) c = asciiLower(c);
    std::vector<std::string> names = {called + ".SPF", called + ".spf", lower + ".spf", called + ".MPF",
                                      called + ".mpf", lower + ".mpf", "_N_" + called + "_SPF", "_N_" + called + "_MPF"};
    std::string looked;
    for (const std::string& folder : options_.subroutineFolders) {
      for (const std::string& file : names) {
        const std::string path = (folder.empty() ? std::string(".") : folder) + "/" + file;
        const long index = files_.load(path, file, n);
        if (index < 0) continue;
        Subprogram found{LineCursor{static_cast<size_t>(index), 0}, {}};
        const KeptFile& kept = files_[static_cast<size_t>(index)];
        for (size_t i = 0; i < std::min(kProcLines, kept.lines.size()); ++i) {
          const std::string_view statement = body(kept.lines[i].text).statement;
          if (keywordOf(statement) != "PROC") continue;
          found.parameters = procParameters(statement.data() + 4, statement.data() + statement.size(),
                                            kept.lines[i].number);
          found.start = LineCursor{static_cast<size_t>(index), i + 1};
          break;
        }
        return &(subprograms_[called] = found);
      }
      looked += (looked.empty() ? "" : ", ") + (folder.empty() ? std::string(".") : folder);
    }
    missing = missing_.emplace(called, looked.empty() ? std::string("no folder given") : "in " + looked).first;
  }
  if (!required || options_.passMissingCalls) return nullptr;
  const std::string nearest = nearestSiemensKeyword(called);
  fail(n, "subprogram " + called + " is not found (looked for " + called + ".SPF, " + called + ".MPF and _N_" + called +
              "_SPF " + missing->second + "; the control stops here too, alarm 14011): put " + called +
              ".SPF beside the program or give its folder" +
              (nearest.empty() ? std::string() : "; or is it a misspelt " + nearest + "?"));
}

bool SiemensProgram::callStatement(const std::string& called, std::string_view statement, long n) {
  const char* p = statement.data() + called.size();
  const char* end = statement.data() + statement.size();
  const char* q = p;
  skipBlanks(q, end);
  if ((q < end && *q == '=') || called == "DEF"sv) return false;  // an assignment, a declaration
  const bool lNumber = called[0] == 'L' && std::all_of(called.begin() + 1, called.end(), [](char c) { return isAsciiDigit(c); });
  if (!lNumber && (variables_.isVariable(called) || isSiemensKeyword(called))) return false;
  std::string_view arguments;
  p = q;
  if (p < end && *p == '(') arguments = parenthesised(p, end, n);
  long passes = 1;
  skipBlanks(p, end);
  if (p < end && (*p == 'P' || *p == 'p')) {
    ++p;
    skipBlanks(p, end);
    if (p < end && *p == '=') ++p;
    const double value = variables_.evaluate(p, end, n);
    if (!(value >= 1 && value == std::floor(value) && value <= static_cast<double>(options_.maxLoopIterations)))
      fail(n, called + " P" + number(value) + ": a call's passes are a whole number from 1 to " +
                  std::to_string(options_.maxLoopIterations));
    passes = static_cast<long>(value);
  }
  if (!endOfStatement(p, end))
    fail(n, "the call of " + called + " shares its block with '" + std::string(trimmed(std::string_view(p, end - p)).substr(0, 24)) +
                "': put the call on a block of its own (with P=<passes>)");
  // A standard cycle is a subprogram of the control's cycle folder: called when given, else named by the
  // interpreter as motion it does not model.
  const Subprogram* target = subprogram(called, n, !isStandardCycle(called));
  if (target == nullptr) return false;  // missing, and to be skipped: the interpreter counts it
  call(*target, called, arguments, passes, n);
  return true;
}

void SiemensProgram::call(const Subprogram& target, const std::string& called, std::string_view arguments, long passes,
                          long n) {
  if (static_cast<int>(frames_.size()) >= kMaxSiemensCallDepth)
    fail(n, called + ": calls nested more than " + std::to_string(kMaxSiemensCallDepth) +
                " levels deep (the 840D's limit; a subprogram that calls itself without end?)");
  Frame frame{target.start, cursor_, passes - 1, n, {}, {}};
  const std::vector<std::string_view> parts = commaParts(arguments);
  if (parts.size() > target.parameters.size())
    fail(n, called + " takes " + std::to_string(target.parameters.size()) + " parameters (its PROC line names them), the "
                "call gives " + std::to_string(parts.size()));
  for (size_t i = 0; i < target.parameters.size(); ++i) {
    double value = 0.0;  // a parameter the call leaves out is 0
    if (i < parts.size()) {
      const std::string_view argument = trimmed(parts[i]);
      if (!argument.empty() && argument.front() != '"') {
        const char* a = argument.data();
        const char* e = a + argument.size();
        value = variables_.evaluate(a, e, n);
        if (!endOfStatement(a, e)) fail(n, called + ": argument " + std::to_string(i + 1) + " ('" + std::string(argument) +
                                               "') is not an expression");
      }
    }
    frame.arguments.emplace_back(target.parameters[i], value);
  }
  variables_.enterCall();
  for (const auto& [parameter, value] : frame.arguments) variables_.declareLocal(parameter, value);
  frames_.push_back(std::move(frame));
  cursor_ = target.start;
}

void SiemensProgram::leave() {
  Frame& frame = frames_.back();
  variables_.leaveCall();
  if (frame.repeatsLeft > 0) {
    --frame.repeatsLeft;
    frame.structures.clear();
    variables_.enterCall();
    for (const auto& [parameter, value] : frame.arguments) variables_.declareLocal(parameter, value);
    cursor_ = frame.start;
    return;
  }
  cursor_ = frame.returnTo;
  frames_.pop_back();
}

std::string_view SiemensProgram::computedCycleArguments(std::string_view statement, long n) {
  const size_t at = statement.find("CYCLE");
  if (at == std::string_view::npos) return statement;
  size_t open = at + 5;
  while (open < statement.size() && isDigit(statement[open])) ++open;
  if (open == at + 5 || open >= statement.size() || statement[open] != '(') return statement;
  const char* p = statement.data() + open;
  const char* end = statement.data() + statement.size();
  const std::string_view list = parenthesised(p, end, n);
  const std::vector<std::string_view> parts = commaParts(list);
  const bool named = std::any_of(parts.begin(), parts.end(), [](std::string_view part) {
    part = trimmed(part);
    return !part.empty() && part.front() != '"' && std::any_of(part.begin(), part.end(), [](char c) { return isAsciiLetter(c); });
  });
  if (!named) return statement;
  // R parameters and variables in a cycle's arguments (CYCLE81(R1, 0, R2+1, …)): their values, as the control
  // passes them; a name that is neither stays, for the cycle to name
  cycleCall_.assign(statement.substr(0, open + 1));
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string_view part = trimmed(parts[i]);
    if (i > 0) cycleCall_ += ',';
    if (part.empty() || part.front() == '"' || std::none_of(part.begin(), part.end(), [](char c) { return isAsciiLetter(c); })) {
      cycleCall_.append(part);
      continue;
    }
    try {
      const char* a = part.data();
      const char* e = a + part.size();
      const double value = variables_.evaluate(a, e, n);
      if (!endOfStatement(a, e)) throw ParseError(n, "not an expression");
      cycleCall_ += number(value);
    } catch (const ParseError&) {
      cycleCall_.append(part);
    }
  }
  cycleCall_ += ')';
  cycleCall_.append(p, static_cast<size_t>(end - p));
  return cycleCall_;
}

bool SiemensProgram::straight(std::string_view& line, long& number) {
  std::string_view raw;
  long n = 0;
  if (!files_.readNext(raw, n)) {
    ended_ = true;
    return false;
  }
  const Body b = body(raw);
  std::string_view statement = b.statement;  // the end of the line: the same end of its kept copy
  const bool flow = flowOrCall(statement);
  const bool kept = keeping_ || flow || b.sequence >= 0 || !b.label.empty();
  if (kept) {
    keeping_ = true;  // a line a jump, a loop or a repeat may come back to: from here on the lines are kept
    files_.keep(raw, n);
    const std::string_view copy = files_[0].lines.back().text;
    statement = copy.substr(copy.size() - statement.size());
  } else {
    files_.pass();
  }
  if (flow) return false;  // the flow's, kept: the general path runs it
  ++cursor_.index;
  if (kept) letGo();
  if (!addressWordsOnly(statement)) {
    line = variables_.substitute(computedCycleArguments(statement, n), n, rewritten_);
    if (endsProgram(line)) ended_ = true;  // after this line
  } else {
    line = statement;
  }
  number = n;
  lastFile_ = 0;
  return true;
}

void SiemensProgram::letGo() {
  const size_t dropped = files_[0].dropped;
  files_.letGoBehind(cursor_);
  if (files_[0].dropped == dropped) return;
  jumps_.clear();  // what the caches say of the lines let go is no longer true
  closings_.clear();
  if (compiled_.empty()) return;
  compiled_.clear();
  for (size_t f = 0; f < files_.size(); ++f)
    for (KeptLine& kept : files_[f].lines) kept.compiled = -1;
}

bool SiemensProgram::flowOrCall(std::string_view statement) const {
  const std::string keyword = keywordOf(statement);
  if (keyword.empty() || keyword == "DEF"sv || isSiemensKeyword(keyword) || variables_.isVariable(keyword)) return false;
  const char* p = statement.data() + keyword.size();
  const char* end = statement.data() + statement.size();
  skipBlanks(p, end);
  return p >= end || *p != '=';  // NAME=…: an assignment
}

bool SiemensProgram::next(std::string_view& line, long& number) {
  for (;;) {
    // The program read straight through (no loop, call or repeat running): the next line from the source,
    // unless the flow has a statement in it. Until a line with a label, a block number or a statement,
    // nothing can come back to a line: those lines are not even kept (a CAM program, most often).
    if (!ended_ && !leaveAfter_ && frames_.size() == 1 && frames_[0].structures.empty() && cursor_.file == 0 &&
        cursor_.index == files_[0].dropped + files_[0].lines.size()) {
      if (straight(line, number)) return true;
    }
    if (ended_) return false;
    if (leaveAfter_) {
      leaveAfter_ = false;
      leave();
    }
    if (endOfSection()) continue;
    if (frames_.size() == 1 && frames_[0].structures.empty()) letGo();
    KeptLine* stored = files_.fetch(cursor_);
    if (stored == nullptr) {
      if (frames_.size() > 1) {  // a subprogram file that ends without RET or M17: back to the caller
        leave();
        continue;
      }
      return false;
    }
    const long n = stored->number;
    if (++flowLines_ > kMaxFlowLines)
      fail(n, "more than " + std::to_string(kMaxFlowLines) +
                  " lines run through jumps, loops and subprograms: an endless loop? Check its GOTO and loops");
    const size_t file = cursor_.file;
    cursor_ = forward(cursor_);
    std::string_view text;
    try {
      const std::string_view statement = body(stored->text).statement;
      const std::string keyword = keywordOf(statement);
      if (keyword.empty() && addressWordsOnly(statement)) {
        // address words only (X1.5 Y2 F100): no variable, cycle, declaration or program end in it
        line = statement;
        number = n;
        lastFile_ = file;
        return true;
      }
      if (!keyword.empty() && (flowStatement(keyword, statement, n, *stored) || callStatement(keyword, statement, n)))
        continue;
      const std::string_view computed = computedCycleArguments(statement, n);
      if (computed.data() != statement.data()) {  // its text changes from run to run
        text = variables_.substitute(computed, n, rewritten_);
      } else {
        CompiledLine& c = compiled(*stored);
        if (!c.hasText) variables_.compile(statement, n, c.text);
        c.hasText = true;
        text = variables_.run(c.text, statement, n, rewritten_);
      }
    } catch (const ParseError& error) {
      if (files_[file].streaming) throw;
      throw ParseError(n, error.message() + " (in " + files_[file].name + ")");  // the subprogram file it is in
    }
    if (endsProgram(text)) {
      if (frames_.size() > 1) leaveAfter_ = true;
      else ended_ = true;  // after this line
    }
    line = text;
    number = n;
    lastFile_ = file;
    return true;
  }
}

}  // namespace hsm::kinematics::detail
