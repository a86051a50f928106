// Fanuc's and Haas's program flow (internal): the main program and its O-numbered subprograms (after its M30 in
// the same file, or in their own files O1234.nc), M98 / M99 calls and returns (with L repeats and M99 P jumps),
// Haas's M97 local calls, G65 macro calls with Fanuc's argument letters, and Macro B's variables, IF … GOTO,
// IF … THEN, GOTO and WHILE … DO m … END m, as a Fanuc 0i/30i runs them. Gives the lines to run with their
// variables computed (ngc_expression.hpp in Macro B). Lines are kept so that jumps and calls can go back; past
// kMaxKeptLines the oldest are let go (a program that long is drip-fed, and a control cannot jump back in it
// either): a jump to a line let go is refused, naming it.
#pragma once

#include "kinematics/gcode_lexer.hpp"
#include "kinematics/kept_lines.hpp"
#include "kinematics/ngc_expression.hpp"

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics::detail {

inline constexpr int kMaxMacroCallDepth = 20;  // Fanuc: 10 M98 levels and 5 G65 levels; generously above both

struct MacroOptions {
  std::vector<std::string> subroutineFolders;  // searched in order for O1234.nc and the like
  long maxLoopIterations = 10'000'000;         // turns of one WHILE loop, or jumps back to one line
  bool haas = false;                           // M97, and M98 P as the program's number (no repeat digits)
};

class MacroProgram {
public:
  MacroProgram(LineSource& source, MacroOptions options);

  // The next line to run as plain words, and its line number in its file; false at the end of the program.
  bool next(std::string_view& line, long& number);
  // The subprogram file the last line given comes from; empty for the program itself.
  std::string lastFileName() const { return lastFile_ == 0 ? std::string() : files_[lastFile_].name; }
  // Where the tool is (block end in work coordinates, machine, work), for #5001… #5041…: three rows of X Y Z.
  void setPositions(const double (*positions)[3]) { parameters_.setPositions(positions); }

private:
  using Stored = KeptLine;
  using File = KeptFile;
  using Cursor = LineCursor;
  struct Loop {
    int id;
    Cursor start;  // the WHILE (or DO) line
    long turns = 0;
  };
  struct Frame {
    Cursor start;     // the subprogram's first line (for its repeats)
    Cursor returnTo;  // the line after the call
    long repeatsLeft = 0;
    bool macroCall = false;  // G65: its own locals
    long callLine = 0;
    std::vector<Loop> loops;
  };
  enum class Call { None, M98, M97, M99, G65 };

  Stored* fetch(const Cursor& at) { return files_.fetch(at); }
  Cursor forward(Cursor at) const { return Cursor{at.file, at.index + 1}; }
  // Runs a flow statement (IF, WHILE, DO, END, GOTO) at cursor_; false when the line is not one.
  bool flowStatement(std::string_view text, long n);
  // The line of sequence number `sequence` in the current program: forward from `from`, then from its start.
  Cursor sequence(long sequence, Cursor from, long line);
  Cursor programStart(long programNumber, long line);
  void jump(const Cursor& to, long line);
  void call(Call kind, const Line& words, long n);
  void leave(long jumpTo, long n);
  bool endsProgram(std::string_view text) const;
  double condition(const char*& p, const char* end, long n) const;
  [[noreturn]] void fail(long line, const std::string& message) const;

  MacroOptions options_;
  NgcParameters parameters_{ParameterLanguage::MacroB};
  KeptFiles files_;
  std::vector<Frame> frames_;
  std::map<long, Cursor> programs_;          // O-numbers seen, where their first line is
  std::map<std::pair<size_t, size_t>, long> jumpsBack_;  // jumps back to a line, for the loop bound
  Cursor cursor_;
  Cursor mainStart_;
  long flowLines_ = 0;
  bool started_ = false, ended_ = false;
  Call pending_ = Call::None;
  Line pendingWords_;
  long pendingLine_ = 0;
  Line words_;
  std::string rewritten_, rest_;
  size_t lastFile_ = 0;  // the file of the last line given
};

}  // namespace hsm::kinematics::detail
