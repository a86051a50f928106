// G-code reader: FreeCAD/LinuxCNC, grbl, Fanuc, Haas and Siemens 840D dialects (dialect.hpp), streamed line by
// line into motion blocks.
//
// Understood: G0 G1 G2 G3 (IJK, LinuxCNC R, Siemens CR=), G4 dwell, G17 G18 G19, G20 G21 (840D G70 G71
// G700 G710), G90 G91,
// G90.1 G91.1, G9 G60 G61 G61.1 G64 [P [Q]] G641 G642 G643 G644 G645, SOFT BRISK, CYCLE832(tolerance…),
// COMPCAD COMPCURV COMPSURF COMPOF, rotary axes A B C (A=…), G93/G94 (inverse time), 840D TRAORI TRAFOOF,
// orientation vectors A3= B3= C3= (a zero vector is an error), ORIWKS ORIMKS ORIAXES ORIVECT,
// F S T D H M N, comments in ( ) and after ;, block delete /, % lines. Words that change nothing the
// simulation sees (G40, G43, G54…, G80, G94, M3, COMPCAD, FFWON…) are accepted. Anything else is an
// unknown word: skipped and counted, or refused, by option. A malformed line throws ParseError naming the
// line number and the word: numbers are digits with an optional sign and point (no exponent, no nan or
// inf: G-code has none) of at most kMaxWordValue; a line is at most kMaxLineLength characters (a program
// is streamed, so a file without line ends is refused at once instead of read whole); G2/G3 need an end
// point or a centre; a dwell is 0 s or more.
#pragma once

#include "common/error.hpp"
#include "kinematics/dialect.hpp"

#include <Eigen/Core>

#include <istream>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hsm::kinematics {

// Text as it may be shown: bytes outside printable ASCII written as \xNN (a program may hold anything,
// and a message must stay valid text for Python and the GUI).
std::string printable(std::string_view text);

class ParseError : public InputError {
public:
  ParseError(long line, const std::string& message)
      : InputError("line " + std::to_string(line) + ": " + printable(message)), line_(line), message_(message) {}
  long line() const { return line_; }
  const std::string& message() const { return message_; }  // without "line N: "

private:
  long line_;
  std::string message_;
};

inline constexpr size_t kMaxLineLength = 1 << 16;  // characters
inline constexpr double kMaxWordValue = 1e9;       // |value| of any word (mm: a thousand kilometres)

enum class Motion { Rapid, Linear, ArcClockwise, ArcCounterClockwise };

// How the controller may pass from this block to the next.
enum class PathMode {
  ExactStop,   // G60, G61, G9 (this block only): stop at the end
  Continuous,  // G64 on the 840D: no rounding, bounded axis velocity jumps; LinuxCNC G64 without P
  Rounding,    // G641/G642…, LinuxCNC G64 P: corners blended within `tolerance`
};

struct Block {
  Motion motion = Motion::Linear;
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // arcs: centre, in the plane of the start point
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   // arcs: axis of the active plane
  double radius = 0.0;                                // arcs, mm
  double sweep = 0.0;                                 // arcs: signed angle about `normal`, radians
  double feed = 0.0;                                  // programmed, mm/s (0 for G0: rapid)
  PathMode pathMode = PathMode::Continuous;
  double tolerance = 0.0;                             // mm, for Rounding
  // Merging of short G1 blocks before planning: LinuxCNC's naive-CAM tolerance (G64 P… Q…, Q defaults to P;
  // 0: none), and whether the 840D's compressor is on (COMPCAD, COMPCURV, COMPSURF; CYCLE832 with a tolerance).
  double mergeTolerance = 0.0;                        // mm
  bool compressor = false;
  double rateLength = 0.0;                            // mm the block-processing cycle counts (an 840D compressed
                                                      // group, see merging.hpp); 0: the block's own length
  int jerkLimited = -1;                               // 1 SOFT, 0 BRISK, −1 the machine's default
  long line = 0;                                      // source line number, 1-based
  // Rotary axes (4- and 5-axis programs, five_axis_motion.hpp): A B C at the end, deg, as programmed, or the
  // tool-axis vector at the end (840D A3 B3 C3; zero before any); tool tip programmed (840D TRAORI) or machine
  // axes. The start is where the previous block ended (blocks are simulated in order).
  Eigen::Vector3d rotaryEnd = Eigen::Vector3d::Zero(), orientationEnd = Eigen::Vector3d::Zero();
  bool rotary = false;             // the program has rotary words or orientation vectors up to this block
  bool orientationVectors = false; // orientation from A3 B3 C3: interpolated on the great circle (ORIWKS)
  bool orientationByAxes = false;  // ORIMKS / ORIAXES: the rotary axes interpolate linearly
  bool toolTip = false;            // 840D TRAORI on: X Y Z are the tool tip in the workpiece frame
  bool inverseTime = false;        // G93: `feed` is 1 / the block's time, in 1/s

  bool isArc() const { return motion == Motion::ArcClockwise || motion == Motion::ArcCounterClockwise; }
  double length() const;
  // Unit tangent at the start (s = 0) or end (s = 1) of the block.
  Eigen::Vector3d tangent(bool atEnd) const;
  // Point `distance` mm along the block.
  Eigen::Vector3d pointAt(double distance) const;
};

struct ReaderOptions {
  bool refuseUnknownWords = false;   // true: any word not understood is a ParseError
  // A word not understood that would move the machine (an unknown G code, a U V W axis, a frame) stops the
  // reading at its line, naming it; true skips it and counts it, as any other unknown word.
  bool skipUnknownMotion = false;
  bool feedInMmPerSecond = false;    // FreeCAD Path commands store F in mm/s; G-code files use mm/min
  Eigen::Vector3d startPosition = Eigen::Vector3d::Zero();  // where the machine is before the first move
  double arcRadiusTolerance = 0.01;  // mm (plus 0.1 % of the radius) between the start and end radius of an arc
  // The dialect (its language: LinuxCNC's parameters and O-words, Fanuc's Macro B and M98 subprograms, the
  // 840D's words) and the control's power-on state (dialect.hpp); simulate() takes them from the machine.
  ControlConventions conventions;
  std::vector<std::string> subroutineFolders;  // searched in order for subprogram files (NAME.ngc, O1234.nc)
  long maxLoopIterations = 10'000'000;  // turns of one loop before the reading stops, naming it
};

struct ReaderStats {
  long lines = 0;
  long motionBlocks = 0;
  long unknownWords = 0;
  std::map<std::string, long> unknownWordCounts;  // the first 50 distinct unknown words, with counts
  double dwellTime = 0.0;                          // s, from G4
  long toolChanges = 0;
};

// Reads a program from a stream, a block at a time, without loading it whole.
class GcodeReader {
public:
  GcodeReader(std::istream& input, ReaderOptions options = {});
  ~GcodeReader();
  GcodeReader(const GcodeReader&) = delete;
  GcodeReader& operator=(const GcodeReader&) = delete;

  // The next motion block; false at the end of the program.
  bool next(Block& block);
  const ReaderStats& stats() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Convenience: every motion block of a program given as text.
std::vector<Block> readProgram(const std::string& text, const ReaderOptions& options = {});

}  // namespace hsm::kinematics
