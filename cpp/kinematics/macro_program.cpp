#include "kinematics/macro_program.hpp"

#include "common/ascii.hpp"
#include "common/text.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/ngc_program.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace hsm::kinematics::detail {

namespace {
constexpr auto isDigit = isAsciiDigit;
constexpr auto isLetter = isAsciiLetter;
constexpr auto upper = asciiUpper;
constexpr long kLeaderLines = 20;  // a tape leader (a CAM's listing) before the first '%' is at most this long

// The block without its block delete and sequence number; `sequence` gets the N number (−1 without).
std::string_view body(std::string_view text, long& sequence) {
  const char* p = text.data();
  const char* end = p + text.size();
  skipBlanks(p, end);
  if (p < end && *p == '/') ++p;
  skipBlanks(p, end);
  sequence = -1;
  if (p < end && (*p == 'N' || *p == 'n') && p + 1 < end && isDigit(p[1])) {
    sequence = 0;
    for (++p; p < end && isDigit(*p); ++p) sequence = std::min(sequence * 10 + (*p - '0'), 999'999'999L);
    skipBlanks(p, end);
  }
  return std::string_view(p, static_cast<size_t>(end - p));
}

// The letters at the start of `text`, in capitals (a flow keyword: IF, WHILE, DO, END, GOTO, THEN).
std::string keywordAt(const char*& p, const char* end) {
  std::string word;
  while (p < end && isLetter(*p) && word.size() < 8) word += upper(*p++);
  return word;
}

// O1234 at the start of a block (a program's number), or −1.
long programNumber(std::string_view b) {
  if (b.size() < 2 || (b[0] != 'O' && b[0] != 'o') || !isDigit(b[1])) return -1;
  long n = 0;
  for (size_t i = 1; i < b.size() && isDigit(b[i]); ++i) n = std::min(n * 10 + (b[i] - '0'), 999'999'999L);
  return n;
}

bool isPercent(std::string_view b) { return !b.empty() && b[0] == '%'; }
}  // namespace

MacroProgram::MacroProgram(LineSource& source, MacroOptions options)
    : options_(std::move(options)), files_(source) {
  frames_.emplace_back();
}

void MacroProgram::fail(long line, const std::string& message) const {
  const File& file = files_[cursor_.file];
  throw ParseError(line, file.streaming ? message : message + " (in " + file.name + ")");
}

double MacroProgram::condition(const char*& p, const char* end, long n) const {
  skipBlanks(p, end);
  if (p >= end || *p != '[') fail(n, "a condition is written in brackets: IF [#1 GT 10] GOTO 100, WHILE [#2 LT 5] DO 1");
  return NgcExpressionReader(parameters_, n).value(p, end);
}

void MacroProgram::jump(const Cursor& to, long line) {
  if (to.index < files_[to.file].dropped)
    fail(line, "the jump goes back more than " + std::to_string(kKeptBehind) +
                   " lines, which are no longer kept (a program this long is drip-fed: the control cannot either)");
  if (to.file == cursor_.file && to.index < cursor_.index &&
      ++jumpsBack_[{to.file, to.index}] > options_.maxLoopIterations)
    fail(line, "the program has jumped back to the same line " + std::to_string(options_.maxLoopIterations) +
                   " times: an endless loop? Check the condition of its WHILE or GOTO");
  cursor_ = to;
}

MacroProgram::Cursor MacroProgram::sequence(long wanted, Cursor from, long line) {
  // Forward to the end of the program (its M99 / M30 does not stop the search, the next O number or '%' does),
  // then from its first line: as a Fanuc searches.
  const Cursor first = frames_.size() > 1 ? frames_.back().start : mainStart_;
  long seq = 0;
  for (Cursor at = from;; at = forward(at)) {
    Stored* stored = fetch(at);
    if (stored == nullptr) break;
    const std::string_view b = body(stored->text, seq);
    if (at.index != first.index && (programNumber(b) >= 0 || isPercent(b))) break;
    if (seq == wanted) return at;
  }
  for (Cursor at = first; at.index < from.index; at = forward(at)) {
    Stored* stored = fetch(at);
    if (stored == nullptr) break;
    body(stored->text, seq);
    if (seq == wanted) return at;
  }
  fail(line, "N" + std::to_string(wanted) + " is not in this program: the jump has nowhere to go (check its number)");
}

MacroProgram::Cursor MacroProgram::programStart(long number, long line) {
  const auto known = programs_.find(number);
  if (known != programs_.end()) return known->second;
  long seq = 0;
  for (Cursor at{0, files_[0].dropped};; at = forward(at)) {  // the program's own file, read on as needed
    Stored* stored = fetch(at);
    if (stored == nullptr) break;
    if (programNumber(body(stored->text, seq)) == number) return programs_[number] = forward(at);
  }
  std::vector<std::string> tried;
  const std::string digits = std::to_string(number);
  const std::string four = std::string(digits.size() < 4 ? 4 - digits.size() : 0, '0') + digits;
  const std::string five = std::string(digits.size() < 5 ? 5 - digits.size() : 0, '0') + digits;
  for (const std::string& folder : options_.subroutineFolders) {
    for (const std::string& name : {"O" + four, "O" + five, "O" + digits, "o" + four, "o" + five, digits}) {
      for (const char* extension : {".nc", ".NC", ".tap", ".txt", ""}) {
        const std::string path = (folder.empty() ? std::string(".") : folder) + "/" + name + extension;
        if (tried.size() < 6) tried.push_back(path);
        const long loaded = files_.load(path, name + extension, line);
        if (loaded < 0) continue;
        const size_t index = static_cast<size_t>(loaded);
        size_t startAt = 0;  // its O line, or its first line after a '%'
        for (size_t i = 0; i < files_[index].lines.size(); ++i) {
          const std::string_view b = body(files_[index].lines[i].text, seq);
          if (programNumber(b) == number) {
            startAt = i + 1;
            break;
          }
          if (i < static_cast<size_t>(kLeaderLines) && isPercent(b) && startAt == 0) startAt = i + 1;
        }
        return programs_[number] = Cursor{index, startAt};
      }
    }
  }
  std::string where;
  for (const std::string& path : tried) where += (where.empty() ? "" : ", ") + path;
  fail(line, "subprogram O" + four + " is neither in the program nor in a file (looked for " +
                 (where.empty() ? std::string("no folder given") : where + ", ...") +
                 "): put O" + four + ".nc beside the program or give its folder");
}

void MacroProgram::call(Call kind, const Line& words, long n) {
  double p = -1.0, l = 1.0;
  bool hasP = false;
  std::array<double, kMacroLocals> arguments;
  arguments.fill(std::numeric_limits<double>::quiet_NaN());
  // G65's argument letters (Fanuc's argument specification I) and the local each one sets
  static constexpr const char* kLetters = "ABCIJKDEFHMQRSTUVWXYZ";
  static constexpr int kLocals[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  for (int i = 0; i < words.wordCount; ++i) {
    const Word& w = words.words[static_cast<size_t>(i)];
    if (w.letter == 'P') {
      p = w.value;
      hasP = true;
    } else if (w.letter == 'L') {
      l = w.value;
    } else if (kind == Call::G65 && w.letter != 'G' && w.letter != 'N' && w.letter != 'O') {
      const char* at = std::strchr(kLetters, w.letter);
      if (at != nullptr) arguments[static_cast<size_t>(kLocals[at - kLetters] - 1)] = w.value;
    }
  }
  if (kind == Call::M99) return leave(hasP ? std::lround(p) : -1, n);
  const char* name = kind == Call::M98 ? "M98" : kind == Call::M97 ? "M97" : "G65";
  if (!hasP || p < 0 || p != std::floor(p)) fail(n, std::string(name) + " needs P: the " +
                                                      (kind == Call::M97 ? "sequence number (N) to call" : "program number to call"));
  long target = std::lround(p);
  if (kind == Call::M98 && !options_.haas && target > 9999 && l == 1.0) {  // Fanuc 0: M98 P<repeats><program>
    l = static_cast<double>(target / 10000);
    target %= 10000;
  }
  if (!(l >= 0 && l <= 9999 && l == std::floor(l)))
    fail(n, std::string(name) + " L" + number(l) + ": the repeat count is a whole number from 0 to 9999");
  if (l == 0) return;
  if (static_cast<int>(frames_.size()) > kMaxMacroCallDepth)
    fail(n, std::string(name) + ": calls nested more than " + std::to_string(kMaxMacroCallDepth) +
                " deep (a subprogram that calls itself without end?)");
  const Cursor start = kind == Call::M97 ? sequence(target, cursor_, n) : programStart(target, n);
  if (kind == Call::G65) parameters_.enterMacroCall(arguments);
  frames_.push_back(Frame{start, cursor_, static_cast<long>(l) - 1, kind == Call::G65, n, {}});
  cursor_ = start;
}

void MacroProgram::leave(long jumpTo, long n) {
  if (frames_.size() == 1) {
    // M99 in the main program: a Fanuc runs it again without end; one pass is what is timed. M99 P: a jump.
    if (jumpTo < 0) ended_ = true;
    else jump(sequence(jumpTo, cursor_, n), n);
    return;
  }
  Frame& frame = frames_.back();
  if (frame.repeatsLeft > 0) {
    --frame.repeatsLeft;
    frame.loops.clear();
    cursor_ = frame.start;
    return;
  }
  if (frame.macroCall) parameters_.leaveCall();
  const Cursor back = frame.returnTo;
  frames_.pop_back();
  cursor_ = back;
  if (jumpTo >= 0) cursor_ = sequence(jumpTo, back, n);
}

bool MacroProgram::flowStatement(std::string_view b, long n) {
  const char* p = b.data();
  const char* end = p + b.size();
  const char* start = p;
  const std::string keyword = keywordAt(p, end);
  if (keyword.size() < 2) return false;
  const NgcExpressionReader reader(parameters_, n);
  auto target = [&]() {  // GOTO's sequence number: a value, a #variable or an [expression]
    const double v = reader.value(p, end);
    if (!(v >= 0 && v == std::floor(v))) fail(n, "GOTO " + number(v) + ": a sequence number is a whole number");
    return static_cast<long>(v);
  };
  auto& loops = frames_.back().loops;
  const Cursor here{cursor_.file, cursor_.index - 1};
  if (keyword == "GOTO") {
    jump(sequence(target(), here, n), n);
  } else if (keyword == "IF") {
    const bool holds = condition(p, end, n) != 0.0;
    skipBlanks(p, end);
    const std::string then = keywordAt(p, end);
    if (then == "GOTO") {
      const long to = target();
      if (holds) jump(sequence(to, here, n), n);
    } else if (then == "THEN") {
      skipBlanks(p, end);
      if (holds) {
        if (p < end && *p != '#') fail(n, "IF ... THEN runs an assignment here (IF [#1 GT 0] THEN #2=1): move the block "
                                          "after THEN to its own line behind an IF ... GOTO");
        substituteParameters(std::string_view(p, static_cast<size_t>(end - p)), n, parameters_, rewritten_);
      }
    } else {
      fail(n, "IF [condition] is followed by GOTO n or THEN #var=value");
    }
  } else if (keyword == "WHILE" || keyword == "DO") {
    const bool holds = keyword == "DO" || condition(p, end, n) != 0.0;
    skipBlanks(p, end);
    if (keyword == "WHILE" && keywordAt(p, end) != "DO") fail(n, "WHILE [condition] is followed by DO m");
    const double id = reader.value(p, end);
    if (!(id >= 1 && id <= 3 && id == std::floor(id)))
      fail(n, "DO " + number(id) + ": a loop's number is 1, 2 or 3 (Fanuc)");
    const bool again = !loops.empty() && loops.back().start.index == here.index && loops.back().start.file == here.file;
    if (holds) {
      if (!again) loops.push_back(Loop{static_cast<int>(id), here, 0});
    } else {
      if (again) loops.pop_back();
      long seq = 0;
      for (Cursor at = cursor_;; at = forward(at)) {  // past its END m
        Stored* stored = fetch(at);
        const std::string_view line = stored ? body(stored->text, seq) : std::string_view();
        if (stored == nullptr || programNumber(line) >= 0 || isPercent(line))
          fail(n, "WHILE ... DO " + number(id) + " has no END " + number(id) + " before the program ends: add it");
        const char* q = line.data();
        if (keywordAt(q, line.data() + line.size()) == "END" &&
            NgcExpressionReader(parameters_, stored->number).value(q, line.data() + line.size()) == id) {
          cursor_ = forward(at);
          break;
        }
      }
    }
  } else if (keyword == "END") {
    const double id = reader.value(p, end);
    if (loops.empty() || loops.back().id != id)
      fail(n, "END " + number(id) + " without its WHILE ... DO " + number(id) + " (loops close innermost first)");
    if (++loops.back().turns > options_.maxLoopIterations)
      fail(n, "WHILE ... DO " + number(id) + " has turned " + std::to_string(options_.maxLoopIterations) +
                  " times: an endless loop? Check its condition");
    cursor_ = loops.back().start;
  } else {
    (void)start;
    return false;
  }
  return true;
}

bool MacroProgram::next(std::string_view& line, long& number) {
  if (!started_) {  // a tape leader before a '%' in the first lines, or an NX listing, is not part of the program
    started_ = true;
    long seq = 0;
    int listingRules = 0;
    bool percentSeen = false;  // NX writes its "Information listing" between two lines of '='
    for (Cursor at{0, 0}; at.index < static_cast<size_t>(kDialectLines); at = forward(at)) {
      Stored* stored = fetch(at);
      if (stored == nullptr) break;
      refuseOtherLanguages(stored->text, stored->number);  // before any word of it is run
      if (at.index >= static_cast<size_t>(kLeaderLines)) continue;
      const std::string_view b = body(stored->text, seq);
      if (!percentSeen && b.rfind("=====", 0) == 0 && (at.index == 0 || listingRules == 1) && ++listingRules == 2)
        cursor_ = forward(at);
      if (isPercent(b) && !percentSeen) {
        cursor_ = forward(at);
        percentSeen = true;
      }
    }
    mainStart_ = cursor_;
  }
  for (;;) {
    if (ended_) return false;
    if (frames_.size() == 1 && frames_[0].loops.empty()) files_.letGoBehind(cursor_);
    Stored* stored = fetch(cursor_);
    if (stored == nullptr) {
      if (frames_.size() > 1) {  // a subprogram file that ends without M99: back to the caller
        leave(-1, frames_.back().callLine);
        continue;
      }
      return false;
    }
    if (++flowLines_ > kMaxFlowLines)
      fail(stored->number, "more than " + std::to_string(kMaxFlowLines) +
                               " lines run through jumps and subprograms: an endless loop? Check its GOTO and WHILE");
    const long n = stored->number;
    const Cursor here = cursor_;
    cursor_ = forward(cursor_);
    long seq = 0;
    const std::string_view b = body(stored->text, seq);
    const long program = programNumber(b);
    if (program < 0 && b.size() > 1 && (b[0] == 'O' || b[0] == 'o') && !isDigit(b[1]) && b[1] != '<')
      fail(n, "'" + std::string(b.substr(0, 24)) + "' is not a program number: O is followed by its digits "
              "(O01234); the post left this line for the operator to fill in: write the program's number");
    if (program >= 0 || isPercent(b)) {
      if (program >= 0 && here.index == mainStart_.index && here.file == 0) {  // the main program's own number
        programs_[program] = cursor_;
        continue;
      }
      if (isPercent(b) && here.index == mainStart_.index && here.file == 0) continue;
      if (frames_.size() > 1) {  // the next program begins: this one ended without M99
        leave(-1, n);
        continue;
      }
      return false;  // the main program ends where the next begins, or at '%'
    }
    if (flowStatement(b, n)) continue;
    const std::string_view text = substituteParameters(stored->text, n, parameters_, rewritten_);
    // Calls, returns and the program's end: only lines with an M or a G65 can hold them.
    if (text.find_first_of("Mm") != std::string_view::npos || text.find("65") != std::string_view::npos) {
      words_.parse(text, n);
      Call kind = Call::None;
      bool ends = false;
      for (int i = 0; i < words_.wordCount; ++i) {
        const Word& w = words_.words[static_cast<size_t>(i)];
        if (w.letter == 'G' && w.value == 65) kind = Call::G65;
        if (w.letter != 'M') continue;
        if (w.value == 98) kind = Call::M98;
        if (w.value == 99) kind = Call::M99;
        if (w.value == 97 && options_.haas) kind = Call::M97;
        if (w.value == 30 || w.value == 2) ends = true;
      }
      if (kind == Call::G65) {
        call(kind, words_, n);
        continue;
      }
      if (kind != Call::None) {
        // The block's other words run first (a move on the line of an M98), then the call.
        rest_.clear();
        for (int i = 0; i < words_.wordCount; ++i) {
          const Word& w = words_.words[static_cast<size_t>(i)];
          const bool callWord = w.letter == 'P' || w.letter == 'L' ||
                                (w.letter == 'M' && (w.value == 98 || w.value == 99 || w.value == 97));
          if (!callWord) (rest_ += std::string(w.text)) += ' ';
        }
        call(kind, words_, n);
        if (rest_.empty()) continue;
        line = rest_;
        number = n;
        lastFile_ = here.file;
        return true;
      }
      if (ends && frames_.size() == 1) ended_ = true;
    }
    line = text;
    number = n;
    lastFile_ = here.file;
    return true;
  }
}

}  // namespace hsm::kinematics::detail
