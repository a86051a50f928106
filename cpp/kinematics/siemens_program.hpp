// The 840D's program flow (internal), as the SINUMERIK 840D sl Programming Manual Job Planning ("Flexible NC
// programming", "Subprogram technique") gives it: labels and GOTOF / GOTOB / GOTO / GOTOC (to a label or a block
// number), IF … GOTOx, IF … ELSE … ENDIF, WHILE … ENDWHILE, FOR … TO … ENDFOR, REPEAT … UNTIL, LOOP … ENDLOOP,
// program section repetition (REPEAT label [label] P=n, REPEATB label P=n), and subprograms: L123 and calls by
// name (with arguments for a PROC's parameters, P=n passes), CALL "name", RET / M17 (M2 and M30 in a
// subprogram return too), found as NAME.SPF / .MPF (or the control's _N_NAME_SPF) in the program's folder and
// the folders given. Gives the lines to run with their variables computed (siemens_variables.hpp).
//
// A name alone on its line (or with arguments) that is neither a word the reader knows nor a subprogram found is
// what the control calls a missing program (alarm 14011): refused, naming it and the places looked at, unless
// unknown motion is to be skipped (then the interpreter counts it). Loops and repeats turn at most
// maxLoopIterations times, calls nest at most kMaxSiemensCallDepth deep.
#pragma once

#include "kinematics/gcode_lexer.hpp"
#include "kinematics/kept_lines.hpp"
#include "kinematics/siemens_variables.hpp"

#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace hsm::kinematics::detail {

inline constexpr int kMaxSiemensCallDepth = 16;  // the 840D's program levels, the main program's included

struct SiemensOptions {
  std::vector<std::string> subroutineFolders;  // searched in order for NAME.SPF and the like
  long maxLoopIterations = 10'000'000;         // turns of one loop or repeat, each time it runs
  bool passMissingCalls = false;               // a call to a missing subprogram goes on to the interpreter
};

class SiemensProgram {
public:
  SiemensProgram(LineSource& source, SiemensOptions options);

  // The next line to run as plain words, and its line number in its file; false at the end of the program.
  bool next(std::string_view& line, long& number);
  // The subprogram file the last line given comes from; empty for the program itself.
  std::string lastFileName() const { return lastFile_ == 0 ? std::string() : files_[lastFile_].name; }

private:
  enum class Kind { If, While, For, Repeat, Loop, Section };
  struct Structure {
    Kind kind;
    LineCursor opening;   // the line that opened it (WHILE, FOR…; a section's first line)
    LineCursor stop;      // a section: the line it ends before; returnTo: where the program goes on after it
    LineCursor returnTo;
    std::string variable;  // FOR's counter
    double last = 0.0;     // FOR's end value
    long turns = 0, remaining = 0;
  };
  struct Frame {
    LineCursor start, returnTo;
    long repeatsLeft = 0, callLine = 0;
    std::vector<std::pair<std::string, double>> arguments;  // bound again for each pass
    std::vector<Structure> structures;
  };
  // What running a line again needs without reading its text: its condition, its words' computation.
  struct CompiledLine {
    SiemensExpression condition;
    size_t conditionLength = 0;  // characters of the condition, from where it starts
    bool hasCondition = false, hasText = false;
    SiemensLine text;
  };
  struct Subprogram {
    LineCursor start;                 // the line after its PROC
    std::vector<std::string> parameters;
  };
  // A block split into its parts: sequence number (−1 without), label (empty without), the statement.
  struct Body {
    long sequence = -1;
    std::string_view label, statement;
  };

  static Body body(std::string_view text);
  LineCursor forward(LineCursor at) const { return LineCursor{at.file, at.index + 1}; }
  // Runs the line's flow statement (its keyword `keyword`); false when it is not one.
  bool flowStatement(const std::string& keyword, std::string_view statement, long n, KeptLine& line);
  bool callStatement(const std::string& name, std::string_view statement, long n);
  // P=n (or Pn) from `p`, the passes of a call or a repeat; 1 without.
  double passesOf(const char*& p, const char* end, long n) const;
  // The line of `target` (a label or N123) from `from`: forward, backward, or forward then backward.
  enum class Direction { Forward, Backward, Both, BackwardFirst };  // Both: forward first
  LineCursor find(const std::string& target, Direction direction, LineCursor from, long n, bool required = true);
  // The line closing the structure opened at `opening` (ELSE or ENDIF for an IF, ENDWHILE…).
  LineCursor closing(LineCursor opening, const char* closer, bool elseToo, long n);
  void jump(LineCursor to, long n);
  void loopBack(Structure& s, LineCursor to, const char* what, long n);
  // The condition from `p` (moved past it) of `line`, compiled the first time the line runs.
  bool condition(KeptLine& line, const char*& p, const char* end, long n);
  CompiledLine& compiled(KeptLine& line);
  // The subprogram `name`, loaded on its first call; null when it is missing and not `required` (or missing calls
  // pass), else a ParseError naming it.
  const Subprogram* subprogram(const std::string& name, long n, bool required = true);
  void call(const Subprogram& target, const std::string& name, std::string_view arguments, long passes, long n);
  void leave();
  bool endOfSection();
  // The statement with the values of the variables in its cycle call's arguments (CYCLE81(R1, …)).
  std::string_view computedCycleArguments(std::string_view statement, long n);
  [[noreturn]] void fail(long line, const std::string& message) const;

  SiemensOptions options_;
  KeptFiles files_;
  SiemensVariables variables_;
  std::vector<Frame> frames_;
  std::map<std::string, Subprogram> subprograms_;
  std::vector<CompiledLine> compiled_;  // of the kept lines that have run (KeptLine::compiled)
  std::map<std::string, std::string> missing_;  // names looked for in vain, with the places looked at
  std::map<std::tuple<size_t, size_t, std::string, int>, size_t> jumps_;  // (file, from, target, direction) → line
  std::map<std::pair<size_t, size_t>, size_t> closings_;                  // (file, opening) → closing line
  std::map<std::pair<size_t, size_t>, long> jumpsBack_;  // jumps back to a line, for the loop bound
  LineCursor cursor_;
  long flowLines_ = 0;
  // The program's next line read straight from the source; false for a line the flow runs (kept, at cursor_) or
  // at the end.
  bool straight(std::string_view& line, long& number);
  // Lets the program's lines go that no jump can come back to any more (and what the caches said of them).
  void letGo();
  // Whether the statement is one of the flow's (a jump, a loop, a call…): the lines from it on are kept.
  bool flowOrCall(std::string_view statement) const;
  bool keeping_ = false;
  bool ended_ = false, leaveAfter_ = false;  // leaveAfter_: the line given out returns (M17) after it runs
  std::string rewritten_, cycleCall_;
  size_t lastFile_ = 0;  // the file of the last line given
};

}  // namespace hsm::kinematics::detail
