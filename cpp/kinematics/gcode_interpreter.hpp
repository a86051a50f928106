// The modal interpreter of the G-code reader (internal): the words of a line (gcode_lexer.hpp) applied to
// the modal state of a FreeCAD/LinuxCNC or Siemens 840D controller, giving at most one motion block.
#pragma once

#include "kinematics/gcode_lexer.hpp"

#include <Eigen/Core>

#include <deque>
#include <limits>
#include <string_view>

namespace hsm::kinematics::detail {

// What one line says, before it is applied to the modal state.
struct LineWords {
  int newMotion = -1;  // 0, 1, 2, 3 when the line has G0-G3
  int cycle = 0;       // 73, 81…86, 89 when the line has that canned cycle's G word
  bool cancelCycle = false;  // G80
  bool exactStopHere = false, dwell = false, g64 = false, rigidTap = false;
  bool hasAxis[3] = {false, false, false}, hasOffset[3] = {false, false, false};
  double axis[3] = {0, 0, 0}, offset[3] = {0, 0, 0};
  double radiusWord = 0.0, pWord = -1.0, fWord = 0.0, qWord = 0.0;
  bool hasRadius = false, hasFeed = false, hasP = false, hasQ = false;
  bool hasRotary[3] = {false, false, false}, hasVector[3] = {false, false, false};
  double rotary[3] = {0, 0, 0}, vector[3] = {0, 0, 0};  // A B C (deg), A3 B3 C3

  bool anyAxis() const { return hasAxis[0] || hasAxis[1] || hasAxis[2]; }
  bool anyRotary() const { return hasRotary[0] || hasRotary[1] || hasRotary[2]; }
  bool anyVector() const { return hasVector[0] || hasVector[1] || hasVector[2]; }
  bool anyOffset() const { return hasOffset[0] || hasOffset[1] || hasOffset[2]; }
};

class Interpreter {
public:
  // LinuxCNC's interpreter starts in G99 (a canned cycle retracts to R), as rs274 shows; elsewhere G98.
  explicit Interpreter(const ReaderOptions& options)
      : options_(options), position_(options.startPosition), retractToR_(options.linuxcncLanguage) {}

  // Applies one line (number `lineNumber`); true when it produced a motion block.
  bool interpret(const Line& line, long lineNumber, Block& block);
  // The next block a line made beyond its first (a canned cycle's moves), if any: taken before the next line.
  bool takeQueued(Block& block);
  ReaderStats& stats() { return stats_; }
  const ReaderStats& stats() const { return stats_; }

private:
  // The line's words and keywords; false when the line is to be skipped (a Siemens frame instruction).
  bool collect(const Line& line, LineWords& words);
  // Feed, dwell, G64 and the motion mode of the line.
  void applyModes(const LineWords& words);
  // The motion block of the line, if it moves.
  bool makeBlock(const LineWords& words, Block& block);

  void unknown(std::string_view word);
  void gWord(const Word& w, LineWords& words);
  void mWord(const Word& w);
  void keyword(const Keyword& k, LineWords& words);
  // CYCLE832(tolerance, machining type, …): the 840D high-speed setting. A tolerance selects G642 rounding
  // within it, SOFT and the compressor; no argument (or 0) deselects it (G64, BRISK).
  void cycle832(std::string_view arguments);
  void arc(Block& block, const LineWords& words);
  // A canned cycle's moves at the line's X Y (LinuxCNC's semantics, G17, G90): queued, the first in `block`.
  bool cycleBlocks(const LineWords& words, Block& block);
  // G33.1 rigid tapping: in to the line's end point at the spindle's speed times the pitch K, and back out to
  // where it started (LinuxCNC's RIGID_TAP); queued, the first in `block`.
  bool rigidTapBlocks(const LineWords& words, Block& block);
  Block straightBlock(const Eigen::Vector3d& target, bool rapid) const;
  void rotaryWord(int axis, double value, std::string_view text, LineWords& words);
  // The orientation at the end of the line (A3 B3 C3, a component not given is 0), unit; throws on zero length.
  Eigen::Vector3d orientationTarget(const LineWords& words) const;

  ReaderOptions options_;
  ReaderStats stats_;
  long lineNumber_ = 0;

  // Modal state
  Eigen::Vector3d position_;
  int motion_ = -1;  // 0, 1, 2, 3; −1 before the first motion word
  int plane_ = 17;
  bool absolute_ = true;
  bool arcCentreAbsolute_ = false;
  double unit_ = 1.0;  // mm per program unit
  double feed_ = 0.0;  // mm/s
  double spindle_ = 0.0;  // rev/min, from S
  long zeroFeedLine_ = 0;  // the line that set F0 (legal until a feed move: CAM writes it on rapids)
  PathMode pathMode_ = PathMode::Continuous;
  double tolerance_ = 0.0;
  double roundingTolerance_ = 0.0;  // from CYCLE832 or ADIS; used by G641/G642
  double mergeTolerance_ = 0.0;     // LinuxCNC G64 Q (naive CAM)
  bool compressor_ = false;         // 840D COMPCAD/COMPCURV/COMPSURF
  int jerkLimited_ = -1;
  Eigen::Vector3d rotary_ = Eigen::Vector3d::Zero();       // A B C, deg
  Eigen::Vector3d orientation_ = Eigen::Vector3d::Zero();  // last A3 B3 C3 (unit), zero before any
  bool rotarySeen_ = false, toolTip_ = false, orientationByAxes_ = false, inverseTime_ = false;

  // Canned cycles: the cycle in effect (0: none), its sticky words (R, Z, Q in mm; P in s), the Z the cycles
  // started from (G98 returns there, or to R if higher; G99 to R), and the blocks still to hand out.
  int cycle_ = 0;
  bool retractToR_ = false;
  double cycleR_ = std::numeric_limits<double>::quiet_NaN(), cycleZ_ = std::numeric_limits<double>::quiet_NaN();
  double cycleQ_ = 0.0, cycleP_ = 0.0, cycleStartZ_ = 0.0;
  std::deque<Block> queued_;
};

}  // namespace hsm::kinematics::detail
