// LinuxCNC's O-word program flow (internal): subroutines (in the program or in their own files), loops and
// conditions, as LinuxCNC 2.9's rs274ngc runs them. Gives the lines to run, in the order the controller runs
// them, with their parameters and expressions already computed (ngc_expression.hpp). A program without O-words
// streams through untouched; the lines of subroutines and loops (and those read ahead to find them) are kept
// so that calls and loops can go back, the others stream through.
#pragma once

#include "kinematics/gcode_lexer.hpp"
#include "kinematics/ngc_expression.hpp"

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics::detail {

inline constexpr int kMaxCallDepth = 50;
inline constexpr long kMaxFlowLines = 200'000'000;           // lines run from kept lines (loops, subroutines)

struct NgcOptions {
  std::vector<std::string> subroutineFolders;  // searched in order for NAME.ngc of an `o<name> call`
  long maxLoopIterations = 10'000'000;         // of one loop, each time it runs
};

class NgcProgram {
public:
  NgcProgram(LineSource& source, NgcOptions options) : source_(source), options_(std::move(options)) {
    files_.push_back(File{"the program", {}, true});
    frames_.emplace_back();
  }

  // The next line to run as plain words, and its line number in its file; false at the end of the program.
  // Throws ParseError naming the line (and the file of a subroutine) for what cannot run.
  bool next(std::string_view& line, long& number);
  // The subprogram file the last line given comes from; empty for the program itself.
  std::string lastFileName() const { return lastFile_ == 0 ? std::string() : files_[lastFile_].name; }

private:
  struct OWord {
    std::string label, keyword;
    const char* rest = nullptr;  // the arguments after the keyword
    const char* end = nullptr;
  };
  struct Stored {
    std::string text;
    long number;
    int isOWord = -1;  // -1 not looked at yet, 0 no, 1 yes (in `word`): a loop's lines are parsed once
    OWord word;
  };
  struct File {
    std::string name;
    std::deque<Stored> lines;  // a deque: kept lines stay where they are while more are read
    bool streaming;  // the program itself: its lines come from the source as they are needed
  };
  struct Cursor {
    size_t file = 0, index = 0;
  };
  enum class Kind { While, Do, If, Repeat };
  struct Structure {
    std::string label;
    Kind kind;
    Cursor start;
    long remaining = 0, iterations = 0;
  };
  struct Frame {
    std::string label;
    Cursor returnTo;
    long callLine = 0;
    std::vector<Structure> structures;
  };

  // The kept line at `at`, read from the source when the program's next line is needed; null at its end.
  Stored* fetch(const Cursor& at);
  static bool parseOWord(std::string_view text, OWord& o);
  // The kept line's O-word, parsed the first time it is asked for; null for another line.
  static const OWord* oWordOf(Stored& line);
  // Runs the O-word line at cursor_ (line `n` of its file), moving the cursor to the line that runs next.
  void runOWord(const OWord& o, long n);
  // The first O-word line after `from` with `label` and one of `keywords`; throws naming `what` is missing.
  Cursor find(Cursor from, const std::string& label, std::initializer_list<const char*> keywords,
              const std::string& what, long line);
  Cursor definition(const std::string& label, long line);
  double condition(const OWord& o, long line) const;
  void call(const OWord& o, long n);
  void leave(const OWord& o, long n);
  void loopAgain(Structure& s, long line);
  Structure* innermost(const std::string& label);
  [[noreturn]] void fail(long line, const std::string& message) const;

  LineSource& source_;
  NgcOptions options_;
  NgcParameters parameters_;
  std::deque<File> files_;  // a deque: a file never moves while its lines are referred to (a call reads another file)
  std::vector<Frame> frames_;
  std::map<std::string, Cursor> subroutines_;
  Cursor cursor_;
  bool keeping_ = false;  // from the first O-word line on, lines of O-word structures are kept
  long streamed_ = 0;     // lines read from the source
  long flowLines_ = 0;
  std::string rewritten_;
  size_t lastFile_ = 0;  // the file of the last line given
};

}  // namespace hsm::kinematics::detail
