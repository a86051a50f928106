#include "kinematics/ngc_program.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace hsm::kinematics::detail {

namespace {
constexpr auto isLetter = isAsciiLetter;
constexpr auto isDigit = isAsciiDigit;
constexpr auto lower = asciiLower;

std::string shown(const std::string& label) { return "o" + label; }

bool hasKeyword(const std::string& keyword, std::initializer_list<const char*> keywords) {
  return std::any_of(keywords.begin(), keywords.end(), [&](const char* k) { return keyword == k; });
}
}  // namespace

void NgcProgram::fail(long line, const std::string& message) const {
  const File& file = files_[cursor_.file];
  throw ParseError(line, file.streaming ? message : message + " (in " + file.name + ")");
}

const NgcProgram::OWord* NgcProgram::oWordOf(Stored& line) {
  if (line.isOWord < 0) line.isOWord = parseOWord(line.text, line.word) ? 1 : 0;
  return line.isOWord ? &line.word : nullptr;
}

NgcProgram::Stored* NgcProgram::fetch(const Cursor& at) {
  File& file = files_[at.file];
  while (at.index >= file.lines.size()) {
    if (!file.streaming) return nullptr;
    std::string_view raw;
    if (!source_.next(raw)) return nullptr;
    file.lines.push_back(Stored{std::string(raw), ++streamed_, -1, {}});
  }
  return &file.lines[at.index];
}

bool NgcProgram::parseOWord(std::string_view text, OWord& o) {
  const char* p = text.data();
  const char* end = p + text.size();
  skipBlanks(p, end);
  if (p < end && *p == '/') ++p;
  skipBlanks(p, end);
  if (p < end && (*p == 'N' || *p == 'n')) {  // a line number before the O-word
    const char* q = p + 1;
    while (q < end && (isDigit(*q) || *q == ' ' || *q == '.')) ++q;
    if (q > p + 1) p = q;
  }
  if (!(p < end && (*p == 'O' || *p == 'o'))) return false;
  ++p;
  skipBlanks(p, end);
  o.label.clear();
  if (p < end && *p == '<') {
    for (; p < end && *p != '>'; ++p)
      if (*p != ' ' && *p != '\t') o.label += lower(*p);
    if (p == end) return false;  // not an O-word: reading the line names the '<' 
    o.label += '>';
    ++p;
  } else {
    for (; p < end && (isDigit(*p) || *p == ' ' || *p == '\t'); ++p)
      if (isDigit(*p)) o.label += *p;
    if (o.label.empty()) return false;
    o.label.erase(0, std::min(o.label.find_first_not_of('0'), o.label.size() - 1));  // o0100 is o100
  }
  skipBlanks(p, end);
  o.keyword.clear();
  while (p < end && isLetter(*p)) o.keyword += lower(*p++);
  o.rest = p;
  o.end = end;
  return true;
}

double NgcProgram::condition(const OWord& o, long line) const {
  const char* p = o.rest;
  skipBlanks(p, o.end);
  if (p >= o.end || *p != '[') fail(line, shown(o.label) + " " + o.keyword + " needs a condition in brackets: " +
                                              shown(o.label) + " " + o.keyword + " [#1 LT 10]");
  return NgcExpressionReader(parameters_, line).value(p, o.end);
}

NgcProgram::Structure* NgcProgram::innermost(const std::string& label) {
  auto& structures = frames_.back().structures;
  for (auto s = structures.rbegin(); s != structures.rend(); ++s)
    if (s->label == label) return &*s;
  return nullptr;
}

NgcProgram::Cursor NgcProgram::find(Cursor from, const std::string& label, std::initializer_list<const char*> keywords,
                                    const std::string& what, long line) {
  for (Cursor at{from.file, from.index + 1};; ++at.index) {
    Stored* stored = fetch(at);
    if (stored == nullptr) fail(line, shown(label) + " has no " + what + ": the program ends first; add it");
    const OWord* o = oWordOf(*stored);
    if (o != nullptr && o->label == label && hasKeyword(o->keyword, keywords)) return at;
  }
}

NgcProgram::Cursor NgcProgram::definition(const std::string& label, long line) {
  const auto known = subroutines_.find(label);
  if (known != subroutines_.end()) return known->second;
  // Defined further on in this file (rs274ngc searches forward), or, for o<name>, in NAME.ngc.
  for (Cursor at{cursor_.file, cursor_.index + 1};; ++at.index) {
    Stored* stored = fetch(at);
    if (stored == nullptr) break;
    const OWord* o = oWordOf(*stored);
    if (o != nullptr && o->label == label && o->keyword == "sub") return subroutines_[label] = at;
  }
  if (label.front() != '<') fail(line, "o" + label + " call: the program has no o" + label + " sub: define it");
  const std::string name = label.substr(1, label.size() - 2);
  std::vector<std::string> tried;
  for (const std::string& folder : options_.subroutineFolders) {
    const std::string path = (folder.empty() ? std::string(".") : folder) + "/" + name + ".ngc";
    tried.push_back(path);
    std::ifstream stream(path, std::ios::binary);
    if (!stream) continue;
    File file{name + ".ngc", {}, false};
    LineSource lines(stream);
    std::string_view raw;
    for (long n = 1; lines.next(raw); ++n) file.lines.push_back(Stored{std::string(raw), n, -1, {}});
    files_.push_back(std::move(file));
    const size_t index = files_.size() - 1;
    for (size_t i = 0; i < files_[index].lines.size(); ++i) {
      const OWord* o = oWordOf(files_[index].lines[i]);
      if (o != nullptr && o->label == label && o->keyword == "sub") return subroutines_[label] = Cursor{index, i};
    }
    fail(line, "o" + label + " call: " + path + " has no o" + label + " sub: define it there");
  }
  std::string where;
  for (const std::string& path : tried) where += (where.empty() ? "" : ", ") + path;
  fail(line, "o" + label + " call: no subroutine o" + label + " in the program, nor a file " + name + ".ngc (looked for " +
                 (where.empty() ? std::string("no folder given") : where) + "): put it beside the program or give its folder");
}

void NgcProgram::call(const OWord& o, long n) {
  if (static_cast<int>(frames_.size()) > kMaxCallDepth)
    fail(n, shown(o.label) + " call: subroutines nested more than " + std::to_string(kMaxCallDepth) +
                          " deep (a subroutine that calls itself without end?)");
  std::vector<double> arguments;
  const NgcExpressionReader reader(parameters_, n);
  for (const char* p = o.rest;;) {  // the arguments first: the search for the definition reads more lines
    skipBlanks(p, o.end);
    if (p >= o.end || *p == ';' || *p == '(') break;
    if (*p != '[') fail(n, shown(o.label) + " call: arguments are given in brackets: " + shown(o.label) + " call [1] [2.5]");
    if (arguments.size() == static_cast<size_t>(kSubroutineArguments))
      fail(n, shown(o.label) + " call: more than " + std::to_string(kSubroutineArguments) + " arguments");
    arguments.push_back(reader.value(p, o.end));
  }
  const Cursor start = definition(o.label, n);
  parameters_.enterCall(arguments);
  frames_.push_back(Frame{o.label, Cursor{cursor_.file, cursor_.index + 1}, n, {}});
  cursor_ = Cursor{start.file, start.index + 1};
}

void NgcProgram::leave(const OWord& o, long n) {
  if (frames_.size() < 2 || frames_.back().label != o.label)
    fail(n, shown(o.label) + " " + o.keyword + " outside a call of " + shown(o.label) + ": check the O-words");
  const char* p = o.rest;
  skipBlanks(p, o.end);
  double value = 0.0;
  const bool returned = p < o.end && *p == '[';
  if (returned) value = NgcExpressionReader(parameters_, n).value(p, o.end);
  parameters_.leaveCall();
  parameters_.setNamed("_value", value);
  parameters_.setNamed("_value_returned", returned ? 1.0 : 0.0);
  cursor_ = frames_.back().returnTo;
  frames_.pop_back();
}

void NgcProgram::loopAgain(Structure& s, long line) {
  if (++s.iterations > options_.maxLoopIterations)
    fail(line, shown(s.label) + " has looped " + std::to_string(options_.maxLoopIterations) +
                   " times: an endless loop? Check its condition (or split the loop)");
}

void NgcProgram::runOWord(const OWord& o, long n) {
  auto& structures = frames_.back().structures;
  const std::string& k = o.keyword;
  if (k == "sub") {  // a definition met in the flow: skipped, remembered
    subroutines_[o.label] = cursor_;
    cursor_ = find(cursor_, o.label, {"endsub"}, "endsub", n);
    ++cursor_.index;
  } else if (k == "endsub" || k == "return") {
    leave(o, n);
  } else if (k == "call") {
    call(o, n);
  } else if (k == "do") {
    structures.push_back(Structure{o.label, Kind::Do, cursor_});
    ++cursor_.index;
  } else if (k == "while") {
    Structure* s = innermost(o.label);
    const bool closesDo = s != nullptr && s->kind == Kind::Do;
    const bool again = s != nullptr && s->kind == Kind::While && s->start.index == cursor_.index &&
                       s->start.file == cursor_.file;
    if (condition(o, n) != 0.0) {
      if (closesDo) {
        loopAgain(*s, n);
        cursor_ = Cursor{s->start.file, s->start.index + 1};
        return;
      }
      if (again)
        loopAgain(*s, n);
      else
        structures.push_back(Structure{o.label, Kind::While, cursor_});
      ++cursor_.index;
    } else {
      if (closesDo || again) structures.erase(structures.begin() + (s - structures.data()), structures.end());
      if (!closesDo) cursor_ = find(cursor_, o.label, {"endwhile"}, "endwhile", n);
      ++cursor_.index;
    }
  } else if (k == "endwhile") {
    Structure* s = innermost(o.label);
    if (s == nullptr || s->kind != Kind::While) fail(n, shown(o.label) + " endwhile without its while");
    cursor_ = s->start;
  } else if (k == "if" || k == "elseif" || k == "else") {
    Structure* s = innermost(o.label);
    if (k != "if" && s != nullptr && s->kind == Kind::If) {  // the branch before ran: to the endif
      structures.erase(structures.begin() + (s - structures.data()), structures.end());
      cursor_ = find(cursor_, o.label, {"endif"}, "endif", n);
      ++cursor_.index;
      return;
    }
    if (k == "else" || condition(o, n) != 0.0) {
      structures.push_back(Structure{o.label, Kind::If, cursor_});
      ++cursor_.index;
      return;
    }
    cursor_ = find(cursor_, o.label, {"elseif", "else", "endif"}, "endif", n);  // its line runs next
  } else if (k == "endif") {
    Structure* s = innermost(o.label);
    if (s != nullptr && s->kind == Kind::If) structures.erase(structures.begin() + (s - structures.data()), structures.end());
    ++cursor_.index;
  } else if (k == "repeat") {
    const double count = std::round(condition(o, n));
    if (count >= 1.0) {
      structures.push_back(Structure{o.label, Kind::Repeat, cursor_, static_cast<long>(std::min(count, 1e12))});
      ++cursor_.index;
    } else {
      cursor_ = find(cursor_, o.label, {"endrepeat"}, "endrepeat", n);
      ++cursor_.index;
    }
  } else if (k == "endrepeat") {
    Structure* s = innermost(o.label);
    if (s == nullptr || s->kind != Kind::Repeat) fail(n, shown(o.label) + " endrepeat without its repeat");
    if (--s->remaining > 0) {
      loopAgain(*s, n);
      cursor_ = Cursor{s->start.file, s->start.index + 1};
    } else {
      structures.erase(structures.begin() + (s - structures.data()), structures.end());
      ++cursor_.index;
    }
  } else if (k == "break" || k == "continue") {
    Structure* s = innermost(o.label);
    if (s == nullptr || s->kind == Kind::If) fail(n, shown(o.label) + " " + k + " outside its loop");
    const Kind kind = s->kind;
    const Cursor start = s->start;
    structures.erase(structures.begin() + (s - structures.data()) + 1, structures.end());
    const char* end = kind == Kind::While ? "endwhile" : kind == Kind::Repeat ? "endrepeat" : "while";
    const Cursor close = find(start, o.label, {end}, end, n);
    if (k == "continue") {
      cursor_ = kind == Kind::While ? start : close;  // the loop's test runs next
    } else {
      structures.pop_back();
      cursor_ = Cursor{close.file, close.index + 1};
    }
  } else if (k.empty()) {
    ++cursor_.index;  // O1234: a program number (Fanuc style), nothing to run
  } else {
    fail(n, "'" + k + "' after " + shown(o.label) +
                " is not an O-word LinuxCNC knows (sub endsub call return do while endwhile if elseif else endif "
                "repeat endrepeat break continue)");
  }
}

bool NgcProgram::next(std::string_view& line, long& number) {
  OWord o;
  for (;;) {
    // Streaming: a line from the source that no loop or call can come back to (before the first O-word, or
    // read fresh outside any loop and call) runs without being kept: memory follows the O-word structures,
    // not the program's length.
    const bool fresh = frames_.size() == 1 && frames_[0].structures.empty() && cursor_.file == 0 &&
                       cursor_.index == files_[0].lines.size();
    if (!keeping_ || fresh) {
      std::string_view raw;
      if (!source_.next(raw)) return false;
      number = ++streamed_;
      if (!parseOWord(raw, o)) {
        line = substituteParameters(raw, number, parameters_, rewritten_);
        lastFile_ = 0;
        return true;
      }
      if (o.keyword.empty()) continue;  // O1234: a program number (Fanuc style): nothing kept for it
      keeping_ = true;
      files_[0].lines.push_back(Stored{std::string(raw), number, -1, {}});
      cursor_ = Cursor{0, files_[0].lines.size() - 1};
    }
    Stored* stored = fetch(cursor_);
    if (stored == nullptr) {
      if (frames_.size() > 1)
        fail(frames_.back().callLine, shown(frames_.back().label) + " call: its file ends without " +
                                          shown(frames_.back().label) + " endsub");
      if (!frames_.back().structures.empty()) {
        const Structure& s = frames_.back().structures.back();
        const Stored& opened = files_[s.start.file].lines[s.start.index];
        fail(opened.number, shown(s.label) + " is not closed before the program ends: add its end");
      }
      return false;
    }
    if (++flowLines_ > kMaxFlowLines)
      fail(stored->number, "more than " + std::to_string(kMaxFlowLines) +
                               " lines run through loops and subroutines: an endless loop? Check the O-words");
    if (const OWord* word = oWordOf(*stored)) {  // stays where it is while runOWord reads more lines (a deque)
      runOWord(*word, stored->number);
      continue;
    }
    number = stored->number;
    lastFile_ = cursor_.file;
    ++cursor_.index;
    try {
      line = substituteParameters(stored->text, number, parameters_, rewritten_);
    } catch (const ParseError& error) {
      if (files_[cursor_.file].streaming) throw;
      fail(number, error.message());
    }
    return true;
  }
}

}  // namespace hsm::kinematics::detail
