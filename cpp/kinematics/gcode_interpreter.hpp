// The modal interpreter of the G-code reader (internal): the words of a line (gcode_lexer.hpp) applied to
// the modal state of a FreeCAD/LinuxCNC or Siemens 840D controller, giving at most one motion block.
#pragma once

#include "kinematics/gcode_lexer.hpp"

#include <Eigen/Core>

#include <array>
#include <deque>
#include <vector>
#include <string>
#include <limits>
#include <string_view>

namespace hsm::kinematics::detail {

// Whether `name` is an 840D instruction the reader takes (reads, accepts without effect, or names as motion it
// cannot see): a name that is not, alone on its block, calls a subprogram (siemens_program.hpp).
bool isSiemensKeyword(std::string_view name);
// TRANS, ROT, SCALE, MIRROR and their additive forms: the coordinates on their line set the frame, they do not
// move the tool.
bool isSiemensFrameKeyword(std::string_view name);
// The comma-separated arguments of an 840D cycle call; an empty one (or a string) is NaN (not given).
std::vector<double> siemensCycleArguments(const std::string& text, const std::string& name, long line);
// The instruction `name` is most likely a misspelling of (one or two letters off), or empty.
std::string nearestSiemensKeyword(std::string_view name);

// What one line says, before it is applied to the modal state.
struct LineWords {
  int newMotion = -1;  // 0, 1, 2, 3 when the line has G0-G3; 4 the 840D's CIP (an arc through a point)
  int cycle = 0;       // 73, 74, 76, 81…89 when the line has that canned cycle's G word
  int home = 0;        // 28 or 30: back to the reference point through the line's point
  bool machineCoordinates = false;  // G53: the line's coordinates are the machine's
  double units = 0.0;  // mm per program unit that G20/G21 (840D G70/G71…) set, applied in the control's order
  double feedUnits = 0.0;  // the same for F: G20/G21, the 840D's G700/G710 (its G70/G71 leave F as it is)
  int siemensCycle = 0;             // 81…89: the line calls CYCLE81…CYCLE89 (with `siemensArguments`)
  std::string_view siemensArguments;
  bool mcall = false;               // 840D MCALL: the line's cycle is called after each move that follows
  int lookAhead = 0;                // G05.1 (51), G05 (50), G08 (80), G187 (1870): a look-ahead mode
  int offsetSetting = 0;            // 10 (G10 L2/L20), 92 (G92): the line sets an offset, it does not move
  bool cancelCycle = false;  // G80
  bool exactStopHere = false, dwell = false, g64 = false, rigidTap = false;
  bool hasAxis[3] = {false, false, false}, hasOffset[3] = {false, false, false};
  // The 840D's X=IC(…) / X=AC(…): this axis incremental (2) or absolute (1) on this block, whatever G90/G91 say;
  // X Y Z then A B C.
  signed char axisMode[6] = {0, 0, 0, 0, 0, 0};
  double axis[3] = {0, 0, 0}, offset[3] = {0, 0, 0};
  double kCount = 0.0;  // K as written (a Fanuc cycle's repeats), without least-increment scaling
  double radiusWord = 0.0, pWord = -1.0, fWord = 0.0, qWord = 0.0, eWord = 0.0, lWord = 0.0;
  bool hasRadius = false, hasFeed = false, hasP = false, hasQ = false, hasE = false, hasL = false;
  bool pHasPoint = false;  // P written with a decimal point (a Fanuc-family dwell in s, else in ms)
  bool hasRotary[3] = {false, false, false}, hasVector[3] = {false, false, false};
  double rotary[3] = {0, 0, 0}, vector[3] = {0, 0, 0};  // A B C (deg), A3 B3 C3
  bool hasThrough[3] = {false, false, false};  // CIP's intermediate point I1= J1= K1=
  double through[3] = {0, 0, 0};

  bool anyAxis() const { return hasAxis[0] || hasAxis[1] || hasAxis[2]; }
  bool anyRotary() const { return hasRotary[0] || hasRotary[1] || hasRotary[2]; }
  bool anyVector() const { return hasVector[0] || hasVector[1] || hasVector[2]; }
  bool anyOffset() const { return hasOffset[0] || hasOffset[1] || hasOffset[2]; }
};

class Interpreter {
public:
  // LinuxCNC's interpreter starts in G99 (a canned cycle retracts to R), as rs274 shows; elsewhere G98.
  explicit Interpreter(const ReaderOptions& options);

  // Applies one line (number `lineNumber`); true when it produced a motion block.
  bool interpret(const Line& line, long lineNumber, Block& block);
  // The next block a line made beyond its first (a canned cycle's moves), if any: taken before the next line.
  bool takeQueued(Block& block);
  // Where the tool is, in program units: the block's end and the work position (rows 0 and 2, in the active
  // frame) and the machine position (row 1), X Y Z each.
  void positions(double (*out)[3]) const;
  ReaderStats& stats() { return stats_; }
  const ReaderStats& stats() const { return stats_; }

private:
  // The line's words and keywords; false when the line is to be skipped (a Siemens frame instruction).
  bool collect(const Line& line, LineWords& words);
  // Feed, units, dwell, G64 and the motion mode of the line, in the control's order.
  void applyModes(const LineWords& words);
  void applyFeed(const LineWords& words);
  void applyOtherModes(const LineWords& words);
  // The motion block of the line, if it moves.
  bool makeBlock(const LineWords& words, Block& block);

  void unknown(std::string_view word);
  // A word not understood that would move the machine: a ParseError unless the options skip it.
  void unknownMotion(std::string_view word, std::string_view what);
  // A dimension word's value in program units: a number without a point counts least increments where the
  // control reads it so (dialect.hpp).
  double dimension(const Word& w, const LineWords& words) const;
  // A dwell's P in seconds: LinuxCNC's and the 840D's in s; a Fanuc's and a Haas's in ms without a point.
  double dwellSeconds(const LineWords& words) const;
  // The 840D's drilling cycle CYCLE81…CYCLE89 with its arguments at the current X Y: queued.
  void siemensDrilling(int number, const std::string& arguments);
  // G28 / G30: rapid to the line's point (the intermediate point), then to the reference point on the axes
  // named; queued, the first in `block`.
  bool homeBlocks(const LineWords& words, Block& block);
  // The 840D's programmable frame: TRANS ATRANS ROT AROT SCALE ASCALE MIRROR AMIRROR.
  void programmableFrame(std::string_view name, const Line& line);
  // CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR …): the swivel of the tool
  // axis (its turn of the rotary axes made the next block) and the swivelled frame; CYCLE800() takes it back.
  void cycle800(const std::string& arguments);
  // The frame's turn, scale and mirror (L = swivel × programmable) made anew, the tool staying where it is.
  void applyFrame();
  // A block made in the frame's coordinates, in the positions' (L applied); nothing without a turn.
  void toPositions(Block& block) const;
  // The target of a G53 / SUPA line: its axes in machine coordinates, the others where the tool is.
  Eigen::Vector3d machineTarget(const LineWords& words) const;
  bool popQueued(Block& block);  // the next queued block, as made
  // G10 L2 / L20 (a work offset's table entry) and G92 (a shift of the coordinates).
  void setOffset(const LineWords& words);
  // Where the program's coordinates put the tool: a programmed point in the active frame, as a position.
  Eigen::Vector3d fromProgram(int axis, double value) const;
  // Each repeat of a canned cycle (K or L), its X Y moved by the line's X Y in G91.
  bool repeatedCycle(const LineWords& words, Block& block);
  void gWord(const Word& w, LineWords& words);
  void mWord(const Word& w);
  void keyword(const Keyword& k, LineWords& words);
  // CYCLE832(tolerance, machining type, …): the 840D high-speed setting. A tolerance selects G642 rounding
  // within it, SOFT and the compressor; no argument (or 0) deselects it (G64, BRISK).
  void cycle832(std::string_view arguments);
  void arc(Block& block, const LineWords& words);
  // CIP: the circle through the start, the intermediate point I1= J1= K1= and the end, in whatever plane they
  // span.
  void arcThrough(Block& block, const LineWords& words) const;
  // A canned cycle's moves at the line's X Y (LinuxCNC's semantics, G17, G90): queued, the first in `block`.
  // The modes a canned cycle's moves borrow (exact stop, the cycle, its feed, the 840D's retract plane), given
  // back when the cycle's moves are queued or the cycle is refused.
  struct CycleModes {
    explicit CycleModes(Interpreter& i) : self(i), mode(i.pathMode_), cycle(i.cycle_), feed(i.feed_) {}
    ~CycleModes() {
      self.pathMode_ = mode;
      self.cycle_ = cycle;
      self.feed_ = feed;
      self.cycleClear_ = std::numeric_limits<double>::quiet_NaN();
    }
    CycleModes(const CycleModes&) = delete;
    CycleModes& operator=(const CycleModes&) = delete;
    Interpreter& self;
    PathMode mode;
    int cycle;
    double feed;
  };
  // One hole: its moves queued (`first`: the line's R, Z and Q are taken, for the holes after it they stand).
  bool cycleBlocks(const LineWords& words, bool first);
  // G33.1 rigid tapping: in to the line's end point at the spindle's speed times the pitch K, and back out to
  // where it started (LinuxCNC's RIGID_TAP); queued, the first in `block`.
  bool rigidTapBlocks(const LineWords& words, Block& block);
  Block straightBlock(const Eigen::Vector3d& target, bool rapid) const;
  // Queues a straight move from where the tool is to `target` (none when it is there).
  void queueMove(const Eigen::Vector3d& target, bool rapid);
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
  double unit_ = 1.0;      // mm per program unit of lengths
  double feedUnit_ = 1.0;  // mm per program unit of F (the 840D's basic system under G70/G71)
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
  double cycleClear_ = std::numeric_limits<double>::quiet_NaN();  // the 840D's RTP: where every hole retracts to
  double cycleDegression_ = 0.0;    // the 840D's CYCLE83 DAM: each peck this much less deep than the last (mm)
  int mcallCycle_ = 0;              // the 840D's modal cycle (MCALL CYCLE8x), 0: none
  std::string mcallArguments_;
  // Work offsets (G54…G59.3: entries 1…9, in machine coordinates), the one in use, and G92's shift. Positions
  // are kept in the frame of the machine file's work offset, so that a program that never changes offsets
  // reads in its own coordinates.
  std::array<Eigen::Vector3d, 10> workOffsets_{};
  int workOffset_ = 1;
  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();  // G92
  // The 840D's frames: a program point p is at work offset + swivelShift_ + swivelTurn_ (programmable_ +
  // programmableLinear_ p), the swivel's (CYCLE800) and the programmable frame's. While their product linear_
  // turns, scales or mirrors (rotated_), position_ and the blocks being made are in its coordinates,
  // inverseLinear_ times the positions', and toPositions() turns the blocks out. Swivelled, the blocks give the
  // tool tip in the workpiece (the 840D's TCP for the swivelled plane) and the tool axis swivelAxis_.
  Eigen::Vector3d programmable_ = Eigen::Vector3d::Zero(), swivelShift_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d programmableLinear_ = Eigen::Matrix3d::Identity(), swivelTurn_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d linear_ = Eigen::Matrix3d::Identity(), inverseLinear_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d swivelAxis_ = Eigen::Vector3d::UnitZ();
  bool rotated_ = false, swivelled_ = false, swivelMovePending_ = false;
  Block swivelMove_;  // CYCLE800's turn of the rotary axes, the machine's linear axes standing
  Eigen::Vector3d frame() const;  // the active frame's origin, in the coordinates position_ is in
  std::deque<Block> queued_;
};

}  // namespace hsm::kinematics::detail
