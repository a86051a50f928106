#include "kinematics/siemens_program.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/gcode_interpreter.hpp"
#include "kinematics/ngc_program.hpp"
#include "kinematics/siemens_text.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace hsm::kinematics::detail {

using namespace std::string_view_literals;

using namespace siemens_text;

namespace {
constexpr auto isDigit = isAsciiDigit;
constexpr auto isLetter = isAsciiLetter;
constexpr auto upper = asciiUpper;

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

double SiemensProgram::passesOf(const char*& p, const char* end, long n) const {
  skipBlanks(p, end);
  if (p >= end || (*p != 'P' && *p != 'p')) return 1.0;
  ++p;
  skipBlanks(p, end);
  if (p < end && *p == '=') ++p;
  return variables_.evaluate(p, end, n);
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
    const double passes = passesOf(p, end, n);
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
