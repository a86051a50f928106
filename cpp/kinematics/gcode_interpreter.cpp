#include "kinematics/gcode_interpreter.hpp"

#include "common/text.hpp"
#include "kinematics/siemens_text.hpp"

#include <Eigen/Geometry>
#include <fast_float/fast_float.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hsm::kinematics::detail {

namespace {
// The 840D instructions the reader knows: read (keyword()), accepted without effect on the motion model, or named
// as motion it cannot see (transformations and frames it does not model).
constexpr std::string_view kSiemensKeywords[] = {
    "SOFT", "BRISK", "CR", "CIP", "I1", "J1", "K1", "ICX", "ICY", "ICZ", "ICA", "ICB", "ICC", "ACX", "ACY", "ACZ",
    "ACA", "ACB", "ACC", "ADIS", "ADISPOS", "T", "MSG", "CYCLE832", "CYCLE800", "CYCLE81", "CYCLE82", "CYCLE83",
    "CYCLE84", "CYCLE85", "CYCLE86", "CYCLE87", "CYCLE88", "CYCLE89", "MCALL", "SUPA", "FNORM", "SETMS", "SBLOF",
    "SBLON", "A3", "B3", "C3", "TRAORI", "TRAFOOF", "ORIMKS", "ORIAXES", "ORIWKS", "ORIVECT", "COMPCAD", "COMPCURV",
    "COMPSURF", "COMPOF", "COMPON", "FFWON", "FFWOF", "UPATH", "SPATH", "DYNNORM", "DYNFINISH", "DYNSEMIFIN",
    "DYNROUGH", "DYNPOS", "TRANS", "ATRANS", "ROT", "AROT", "SCALE", "ASCALE", "MIRROR", "AMIRROR", "RPL",
    // accepted, no effect on the timed motion: preprocessing stops, waits, messages, compensation and feed modes
    "STOPRE", "WAITM", "WAITE", "WAITS", "WAITP", "SETAL", "DISPLOF", "DISPLON", "SAVE", "CFC", "CFTCP", "CFIN",
    "DISC", "OFFN", "CUT2D", "CUT2DF", "CUT3DC", "CUT3DF", "CUT3DFS", "CUT3DFF", "CUT3DCC", "CUT3DCCD", "G_",
    "SPOS", "SPOSA", "SPOF", "SPCON", "SPCOF", "FGROUP", "FGREF", "ORIEULER", "ORIRPY", "ORIPATH", "ORICONCW",
    "ORICONCCW", "ORICURVE", "ORIPLANE", "ACC", "FIFOCTRL", "SOFTA", "BRISKA", "DRIVE", "FINEA", "COARSEA",
    "IPOENDA", "WORKPIECE", "HEAD", "LIMS", "DIAMOF", "DIAMON", "G_FRAME", "TRAILOF", "DRFOF", "PTP",
    "CP", "ORISON", "ORISOF", "TOFFON", "TOFFOF", "D", "M_",
    // named as motion the simulator cannot see
    "TRANSMIT", "TRACYL", "TRAANG", "PAROT", "PAROTOF", "TOROT", "TOROTOF", "TOFRAME", "TOFRAMEX", "TOFRAMEY",
    "TOFRAMEZ", "CT", "BSPLINE", "CSPLINE", "ASPLINE", "POLY"};

// What an instruction (or standard cycle) that moves the machine in ways the simulator does not model is; null
// for the others.
const char* movesUnseen(std::string_view name) {
  // Measuring cycles (CYCLE9xx) probe where the tool is: a few seconds the summary names, no path to time
  if (name.size() == 8 && name.substr(0, 6) == "CYCLE9") return nullptr;
  if (siemens_text::isStandardCycle(std::string(name)))
    return "an 840D standard cycle the simulator does not model (measuring, milling, patterns)";
  for (std::string_view word : {"TRANSMIT", "TRACYL", "TRAANG", "PAROT", "TOROT", "TOFRAME", "TOFRAMEX", "TOFRAMEY",
                                "TOFRAMEZ", "CT", "BSPLINE", "CSPLINE", "ASPLINE", "POLY"})
    if (name == word) return "a transformation, frame, spline or arc form the simulator does not model";
  return nullptr;
}

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}
}  // namespace

bool isSiemensKeyword(std::string_view name) {
  return std::find(std::begin(kSiemensKeywords), std::end(kSiemensKeywords), name) != std::end(kSiemensKeywords);
}

std::string nearestSiemensKeyword(std::string_view name) {
  if (name.size() < 4) return {};
  std::string_view best;
  size_t bestDistance = 3;
  for (std::string_view keyword : kSiemensKeywords) {
    const size_t d = editDistance(name, keyword);
    if (keyword.size() >= 4 && d < bestDistance) {
      best = keyword;
      bestDistance = d;
    }
  }
  return std::string(best);
}

Interpreter::Interpreter(const ReaderOptions& options)
    : options_(options), position_(options.startPosition),
      retractToR_(options.conventions.dialect == Dialect::LinuxCnc || options.conventions.dialect == Dialect::Grbl) {
  workOffsets_.fill(options.conventions.workOffset);
}

Eigen::Vector3d Interpreter::fromProgram(int axis, double value) const {
  Eigen::Vector3d p = position_;
  p[axis] = value * unit_ + frame()[axis];
  return p;
}

void Interpreter::positions(double (*out)[3]) const {
  const Eigen::Vector3d work = (position_ - frame()) / unit_;
  const Eigen::Vector3d machine = (position_ + options_.conventions.workOffset) / unit_;
  for (int a = 0; a < 3; ++a) {
    out[0][a] = out[2][a] = work[a];
    out[1][a] = machine[a];
  }
}

double Interpreter::dimension(const Word& w, const LineWords& words) const {
  if (!options_.conventions.leastIncrementInput || w.text.find('.') != std::string_view::npos) return w.value;
  const double units = words.units > 0.0 ? words.units : unit_;  // a G20 before it on the line counts
  return w.value * (units == 1.0 ? kLeastIncrementMm : kLeastIncrementInch);
}

double Interpreter::dwellSeconds(const LineWords& w) const {
  if (!isFanucFamily(options_.conventions.dialect) || w.pHasPoint) return w.pWord;
  return w.pWord / 1000.0;  // Fanuc: P in ms (no point); Haas: P1000 ms, P1.0 s
}

bool Interpreter::popQueued(Block& block) {
  if (queued_.empty()) return false;
  block = queued_.front();
  queued_.pop_front();
  return true;
}

bool Interpreter::takeQueued(Block& block) {
  if (!popQueued(block)) return false;
  toPositions(block);
  return true;
}

bool Interpreter::interpret(const Line& line, long lineNumber, Block& block) {
  lineNumber_ = lineNumber;
  LineWords words;
  if (!collect(line, words)) return false;
  applyModes(words);
  if (swivelMovePending_) {  // CYCLE800's turn of the rotary axes, as made (machine axes)
    swivelMovePending_ = false;
    block = swivelMove_;
    ++stats_.motionBlocks;
    return true;
  }
  if (!makeBlock(words, block)) return false;
  toPositions(block);
  return true;
}

bool Interpreter::collect(const Line& line, LineWords& words) {
  for (const Keyword& k : line.keywords) {
    if (isSiemensFrameKeyword(k.name)) {
      if (options_.conventions.dialect == Dialect::Siemens840D) programmableFrame(k.name, line);
      else unknownMotion(k.name, "a frame that turns, scales or mirrors the coordinates, in the 840D's language");
      return false;  // the line's coordinates were the frame's, not a move
    }
    keyword(k, words);
  }
  for (int i = 0; i < line.wordCount; ++i) {
    const Word& w = line.words[i];
    switch (w.letter) {
      case 'G': gWord(w, words); break;
      case 'X': case 'Y': case 'Z': {
        const int a = w.letter - 'X';
        if (words.hasAxis[a]) throw ParseError(lineNumber_, std::string("axis ") + w.letter + " given twice");
        words.hasAxis[a] = true;
        words.axis[a] = dimension(w, words);
        break;
      }
      case 'I': case 'J': case 'K': {
        const int a = w.letter - 'I';
        words.hasOffset[a] = true;
        words.offset[a] = dimension(w, words);
        if (a == 2) words.kCount = w.value;
        break;
      }
      case 'A': case 'B': case 'C': rotaryWord(w.letter - 'A', dimension(w, words), w.text, words); break;
      case 'F': words.fWord = w.value; words.hasFeed = true; break;
      case 'R': words.radiusWord = dimension(w, words); words.hasRadius = true; break;
      case 'P':
        words.pWord = w.value;
        words.hasP = true;
        words.pHasPoint = w.text.find('.') != std::string_view::npos;
        break;
      case 'Q': words.qWord = dimension(w, words); words.hasQ = true; break;
      case 'E': words.eWord = w.value; words.hasE = true; break;
      case 'L': words.lWord = w.value; words.hasL = true; break;
      case 'M': mWord(w); break;
      case 'T': ++stats_.toolChanges; break;
      case 'S': spindle_ = w.value; break;
      case 'N': case 'D': case 'H': break;  // no effect on the motion
      case 'U': case 'V': case 'W': unknownMotion(w.text, "an axis the simulator does not have"); break;
      default: unknown(w.text);
    }
  }
  return true;
}

void Interpreter::applyModes(const LineWords& w) {
  // LinuxCNC sets the feed before the line's units ("G-code order of execution"): `G20 F6` is 6 mm/min on a
  // machine that was in G21, as LinuxCNC runs it. Elsewhere the units come first.
  const bool feedBeforeUnits = options_.conventions.dialect == Dialect::LinuxCnc ||
                               options_.conventions.dialect == Dialect::Grbl;
  if (w.units > 0.0 && !feedBeforeUnits) unit_ = w.units;
  if (w.feedUnits > 0.0 && !feedBeforeUnits) feedUnit_ = w.feedUnits;
  applyFeed(w);
  if (w.units > 0.0) unit_ = w.units;
  if (w.feedUnits > 0.0) feedUnit_ = w.feedUnits;
  applyOtherModes(w);
}

void Interpreter::applyFeed(const LineWords& w) {
  if (w.hasFeed && !w.dwell) {
    // F0 is legal where no feed move follows it (FreeCAD CAM's area operations write `G0 F0 Z…`, as LinuxCNC
    // reads it): a feed move at F0 is the error, named with the line that set it.
    if (w.fWord < 0.0 || !std::isfinite(w.fWord))
      throw ParseError(lineNumber_, "feed rate F" + std::to_string(w.fWord) + " must be positive (or 0 on a rapid)");
    // G93: F is the inverse of the block's time in minutes, given on every feed move.
    if (!inverseTime_) {
      feed_ = options_.feedInMmPerSecond ? w.fWord * feedUnit_ : w.fWord * feedUnit_ / 60.0;
      zeroFeedLine_ = w.fWord == 0.0 ? lineNumber_ : 0;
    }
  }
}

void Interpreter::applyOtherModes(const LineWords& w) {
  if (w.dwell) {
    // LinuxCNC G4 P (s), Siemens G4 F (s), Fanuc G4 P (ms) or X (s)
    const bool fanucX = isFanucFamily(options_.conventions.dialect) && w.hasAxis[0] && !w.hasP;
    const double seconds = w.pWord >= 0.0 ? dwellSeconds(w) : fanucX ? w.axis[0] : w.hasFeed ? w.fWord : -1.0;
    if (w.hasP && w.pWord < 0.0)
      throw ParseError(lineNumber_, "G4 P" + number(w.pWord) + ": a dwell lasts 0 s or more; write G4 P<seconds>");
    if (!(seconds >= 0.0)) throw ParseError(lineNumber_, "G4 dwell needs its time: G4 P<seconds> (or F on the 840D)");
    stats_.dwellTime += seconds;
  }
  if (w.g64) {
    pathMode_ = w.pWord > 0.0 ? PathMode::Rounding : PathMode::Continuous;
    tolerance_ = w.pWord > 0.0 ? w.pWord * unit_ : 0.0;
    // LinuxCNC's naive-CAM detector merges G1 moves within Q (Q defaults to P; G64 alone: no merging).
    if (w.hasQ && !(w.qWord >= 0.0))
      throw ParseError(lineNumber_, "G64 Q" + number(w.qWord) + ": the naive-CAM tolerance is 0 or more (mm)");
    mergeTolerance_ = (w.hasQ ? w.qWord : std::max(0.0, w.pWord)) * unit_;
  }
  if (w.offsetSetting != 0) setOffset(w);
  if (w.lookAhead != 0) {
    // On (G05.1 Q1, G05 P10000, G08 P1, G187 with or without P1…P3): corners rounded within E or the machine's
    // tolerance; off (Q0, P0): the control's plain continuous mode.
    if (w.hasE && !(w.eWord > 0.0))
      throw ParseError(lineNumber_, "E" + number(w.eWord) + ": a smoothing tolerance is positive (mm)");
    const bool on = w.lookAhead == 1870 || (w.lookAhead == 51 ? w.hasQ && w.qWord != 0.0 : w.hasP && w.pWord != 0.0);
    pathMode_ = on ? PathMode::Rounding : PathMode::Continuous;
    tolerance_ = on ? (w.hasE && w.eWord > 0.0 ? w.eWord * unit_ : options_.conventions.smoothingTolerance) : 0.0;
  }
  if (w.newMotion >= 0) motion_ = w.newMotion;
  // G0-G3 and G80 end a canned cycle (one modal group); a cycle's G word starts one, from the Z it is at.
  if (w.newMotion >= 0 || w.cancelCycle) cycle_ = 0;
  if (w.cycle > 0) {
    if (cycle_ == 0) cycleStartZ_ = position_.z();
    cycle_ = w.cycle;
  }
}

bool Interpreter::makeBlock(const LineWords& w, Block& block) {
  if (w.offsetSetting != 0) return false;
  if (w.mcall) {  // MCALL CYCLE8x(…): called after each move from the next on; MCALL alone: no more
    mcallCycle_ = w.siemensCycle;
    mcallArguments_ = std::string(w.siemensArguments);
    return false;
  }
  if (w.siemensCycle != 0) {
    siemensDrilling(w.siemensCycle, std::string(w.siemensArguments));
    return popQueued(block);
  }
  if (w.rigidTap) return rigidTapBlocks(w, block);
  if (w.home != 0) return homeBlocks(w, block);
  if (cycle_ != 0 && (w.cycle > 0 || w.anyAxis())) return repeatedCycle(w, block);
  if ((w.newMotion == 2 || w.newMotion == 3) && !w.anyAxis() && !w.anyOffset() && !w.hasRadius)
    throw ParseError(lineNumber_, "G" + std::to_string(w.newMotion) + " without an end point or a centre: an arc "
                                  "needs X/Y/Z and I/J/K (or R); the line moves nothing");
  const bool turns = w.anyRotary() || w.anyVector();
  if (!w.anyAxis() && !turns && !(w.anyOffset() && (motion_ == 2 || motion_ == 3))) return false;
  if (w.dwell) return false;
  if (motion_ < 0) throw ParseError(lineNumber_, "coordinates before any motion mode: start with G0 or G1");

  Eigen::Vector3d target = position_;
  if (w.machineCoordinates) {  // G53, SUPA: absolute machine coordinates, this line only
    target = machineTarget(w);
  } else {
    const Eigen::Vector3d origin = frame();
    for (int a = 0; a < 3; ++a) {
      if (!w.hasAxis[a]) continue;
      const bool absolute = w.axisMode[a] == 0 ? absolute_ : w.axisMode[a] == 1;
      target[a] = absolute ? w.axis[a] * unit_ + origin[a] : position_[a] + w.axis[a] * unit_;
    }
  }
  Eigen::Vector3d rotaryTarget = rotary_;
  for (int a = 0; a < 3; ++a)
    if (w.hasRotary[a])
      rotaryTarget[a] = (w.axisMode[3 + a] == 0 ? absolute_ : w.axisMode[3 + a] == 1) ? w.rotary[a]
                                                                                      : rotary_[a] + w.rotary[a];
  const Eigen::Vector3d orientationTarget = w.anyVector() ? this->orientationTarget(w) : orientation_;
  if (w.anyVector() && w.anyRotary())
    throw ParseError(lineNumber_, "rotary axes and an orientation vector on one line: give the orientation one way");

  block = Block{};
  block.start = position_;
  block.end = target;
  block.line = lineNumber_;
  block.pathMode = w.exactStopHere ? PathMode::ExactStop : pathMode_;
  block.tolerance = tolerance_;
  block.mergeTolerance = pathMode_ == PathMode::Rounding ? mergeTolerance_ : 0.0;
  block.compressor = compressor_;
  block.jerkLimited = jerkLimited_;
  rotarySeen_ = rotarySeen_ || turns;
  block.rotary = rotarySeen_;
  if (rotarySeen_) {
    block.rotaryEnd = rotaryTarget;
    block.orientationEnd = orientationTarget;
    block.orientationVectors = w.anyVector();
    block.orientationByAxes = orientationByAxes_;
    block.toolTip = toolTip_;
  }
  if (motion_ == 0) {
    block.motion = Motion::Rapid;
  } else if (inverseTime_) {
    if (!w.hasFeed)
      throw ParseError(lineNumber_, "G93 (inverse time) needs F on every feed move: F is 1 / the block's minutes");
    block.inverseTime = true;
    block.feed = w.fWord / 60.0;
    block.motion = motion_ == 1 ? Motion::Linear : motion_ == 2 ? Motion::ArcClockwise : Motion::ArcCounterClockwise;
  } else {
    if (feed_ <= 0.0)
      throw ParseError(lineNumber_, zeroFeedLine_ > 0
                                        ? "a feed move at F0 (set at line " + std::to_string(zeroFeedLine_) +
                                              "): program a positive F before G1/G2/G3"
                                        : "no feed rate: program F before the first G1/G2/G3 move");
    block.feed = feed_;
    block.motion = motion_ == 1 ? Motion::Linear : motion_ == 2 ? Motion::ArcClockwise : Motion::ArcCounterClockwise;
  }
  const bool turned = (rotaryTarget - rotary_).squaredNorm() > 0.0 || (orientationTarget - orientation_).squaredNorm() > 0.0;
  if (block.isArc()) {
    if (motion_ == 4) arcThrough(block, w);
    else arc(block, w);
  } else if ((target - position_).squaredNorm() == 0.0 && !turned) {
    return false;  // a move to where the tool already is
  }
  position_ = target;
  rotary_ = rotaryTarget;
  orientation_ = orientationTarget;
  ++stats_.motionBlocks;
  if (mcallCycle_ != 0) siemensDrilling(mcallCycle_, mcallArguments_);  // its moves follow this block's
  return true;
}

Block Interpreter::straightBlock(const Eigen::Vector3d& target, bool rapid) const {
  Block block;
  block.start = position_;
  block.end = target;
  block.line = lineNumber_;
  block.motion = rapid ? Motion::Rapid : Motion::Linear;
  block.feed = rapid ? 0.0 : feed_;
  block.pathMode = pathMode_;
  block.tolerance = tolerance_;
  block.mergeTolerance = pathMode_ == PathMode::Rounding ? mergeTolerance_ : 0.0;
  block.compressor = compressor_;
  block.jerkLimited = jerkLimited_;
  block.rotary = rotarySeen_;
  if (rotarySeen_) {
    block.rotaryEnd = rotary_;
    block.orientationEnd = orientation_;
    block.orientationByAxes = orientationByAxes_;
    block.toolTip = toolTip_;
  }
  return block;
}

void Interpreter::queueMove(const Eigen::Vector3d& target, bool rapid) {
  if ((target - position_).squaredNorm() == 0.0) return;
  queued_.push_back(straightBlock(target, rapid));
  position_ = target;
  ++stats_.motionBlocks;
}

bool Interpreter::repeatedCycle(const LineWords& w, Block& block) {
  // Repeats: L on LinuxCNC and a Haas, K on a Fanuc (L on older ones); K0 / L0 store the cycle's data only.
  const Dialect dialect = options_.conventions.dialect;
  double repeats = 1.0;
  std::string word = "L";
  if (dialect == Dialect::Fanuc && w.hasOffset[2]) {
    repeats = w.kCount;
    word = "K";
  } else if (w.hasL) {
    repeats = w.lWord;
  }
  if (!(repeats >= 0.0 && repeats <= 10000.0 && std::abs(repeats - std::round(repeats)) < 1e-6))
    throw ParseError(lineNumber_, "G" + std::to_string(cycle_) + " " + word + number(repeats) +
                                      ": a cycle's repeat count is a whole number from 0 to 10000");
  // LinuxCNC runs a cycle's moves in exact stop (rs274 shows SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH) around
  // them), as a Fanuc positions at each of its points; the path mode in force comes back after.
  const CycleModes borrowed(*this);
  pathMode_ = PathMode::ExactStop;
  for (long i = 0; i < std::lround(repeats); ++i) cycleBlocks(w, i == 0);
  return popQueued(block);
}

// Canned cycles as LinuxCNC's G-code reference ("G81 Drilling Cycle" and the following sections) and Fanuc's
// manual describe them: the tool goes up to R if below it, across to X Y, down to R, then drills to Z (G81,
// G82 with a dwell of P, G86 and G76 out at rapid; G83 in pecks of Q, back to R after each and rapidly down to
// 0.254 mm above the last depth; G73 in pecks of Q breaking the chip by a 0.254 mm retract; G84, G74, G85 feed
// back out to R, G89 too on a Fanuc and to the clear level on LinuxCNC; G88's manual retract taken as a
// rapid; a Fanuc's G87 back boring from R below the hole up to Z), and retracts to R (G99) or to the Z the
// cycles started from if higher (G98). In G91, X Y move from the last hole, R from the starting Z and Z from R.
bool Interpreter::cycleBlocks(const LineWords& w, bool first) {
  const std::string name = "G" + std::to_string(cycle_);
  if (plane_ != 17) throw ParseError(lineNumber_, name + " in G" + std::to_string(plane_) + ": canned cycles are read in "
                                                  "the XY plane (G17) only");
  if (inverseTime_) throw ParseError(lineNumber_, name + " in G93: give the cycle's feed per minute (G94)");
  const double frameZ = frame().z();
  if (first && w.hasRadius) cycleR_ = absolute_ ? w.radiusWord * unit_ + frameZ : cycleStartZ_ + w.radiusWord * unit_;
  if (first && w.hasAxis[2]) cycleZ_ = absolute_ ? w.axis[2] * unit_ + frameZ : cycleR_ + w.axis[2] * unit_;
  if (first && w.hasQ) cycleQ_ = w.qWord * unit_;
  if (w.hasP && !(w.pWord >= 0.0))
    throw ParseError(lineNumber_, name + " P" + number(w.pWord) + ": a dwell lasts 0 s or more; write P<seconds>");
  if (w.hasP) cycleP_ = dwellSeconds(w);
  if (!std::isfinite(cycleR_) || !std::isfinite(cycleZ_))
    throw ParseError(lineNumber_, name + " needs R (the retract plane) and Z (the hole's bottom), given on its line "
                                         "or an earlier cycle's");
  const bool backBoring = cycle_ == 87;
  if (!backBoring && cycleZ_ > cycleR_)
    throw ParseError(lineNumber_, name + ": the bottom Z" + number(cycleZ_) + " is above the retract plane R" +
                                      number(cycleR_));
  // A Fanuc or a Haas drills G83/G73 with Q0 in one pass (CAM posts write Q0 for "no peck"); LinuxCNC refuses it.
  const bool fanucQ0 = isFanucFamily(options_.conventions.dialect) && cycleQ_ == 0.0;
  const bool pecks = (cycle_ == 83 || cycle_ == 73) && !fanucQ0;
  if (pecks && !(cycleQ_ > 0.0))
    throw ParseError(lineNumber_, name + " needs Q > 0: the depth of each peck (mm)");
  if (pecks && (cycleR_ - cycleZ_) / (cycleDegression_ > 0.0 ? std::min(cycleQ_, cycleDegression_) : cycleQ_) > 1e5)
    throw ParseError(lineNumber_, name + ": " + number(cycleR_ - cycleZ_) + " mm in pecks of Q" + number(cycleQ_) +
                                      " is over 100,000 pecks: give a larger Q");
  if (feed_ <= 0.0)
    throw ParseError(lineNumber_, name + " drills at F0: program a positive F before the cycle");
  double x = position_.x(), y = position_.y();
  if (w.hasAxis[0]) x = absolute_ ? fromProgram(0, w.axis[0]).x() : x + w.axis[0] * unit_;
  if (w.hasAxis[1]) y = absolute_ ? fromProgram(1, w.axis[1]).y() : y + w.axis[1] * unit_;
  const double clear = std::isfinite(cycleClear_)        ? cycleClear_
                       : retractToR_ && !backBoring ? cycleR_
                                                    : std::max(cycleStartZ_, cycleR_);
  constexpr double kPeckClearance = 0.254;  // mm: LinuxCNC's 0.010 inch above the last peck, or back for G73
  auto go = [&](double tx, double ty, double tz, bool rapid) { queueMove(Eigen::Vector3d(tx, ty, tz), rapid); };
  if (position_.z() < cycleR_ && !backBoring) go(position_.x(), position_.y(), cycleR_, true);
  go(x, y, position_.z(), true);
  go(x, y, cycleR_, true);
  if (pecks) {
    double peck = cycleQ_;
    for (double depth = cycleR_; depth > cycleZ_;) {
      const double next = std::max(cycleZ_, depth - peck);
      if (cycleDegression_ > 0.0) peck = std::max(peck - cycleDegression_, cycleDegression_);  // the 840D's DAM
      if (cycle_ == 83 && depth < cycleR_) go(x, y, depth + kPeckClearance, true);
      go(x, y, next, false);
      depth = next;
      if (depth > cycleZ_) go(x, y, cycle_ == 83 ? cycleR_ : depth + kPeckClearance, true);
    }
  } else {
    go(x, y, cycleZ_, false);
  }
  if (cycle_ == 82 || cycle_ == 86 || cycle_ == 89 || cycle_ == 88 || cycle_ == 76) stats_.dwellTime += cycleP_;
  // LinuxCNC's G89 feeds out to the clear level (rs274 shows it); a Fanuc's, like G85, to R
  const bool feedsToClear = cycle_ == 89 && !isFanucFamily(options_.conventions.dialect);
  if (feedsToClear) go(x, y, clear, false);
  if (cycle_ == 84 || cycle_ == 74 || cycle_ == 85 || (cycle_ == 89 && !feedsToClear)) go(x, y, cycleR_, false);
  go(x, y, clear, true);
  return true;
}

// The comma-separated arguments of an 840D cycle call; an empty one is NaN (not given).
std::vector<double> siemensCycleArguments(const std::string& text, const std::string& name, long line) {
  std::vector<double> values;
  size_t from = 0;
  for (;;) {
    const size_t comma = std::min(text.find(',', from), text.size());
    std::string_view item(text.data() + from, comma - from);
    while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) item.remove_prefix(1);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.remove_suffix(1);
    double value = std::numeric_limits<double>::quiet_NaN();
    if (!item.empty() && item.front() != '"') {
      const char* begin = item.data() + (item.front() == '+' ? 1 : 0);
      const auto parsed = fast_float::from_chars(begin, item.data() + item.size(), value, fast_float::chars_format::fixed);
      if (parsed.ec != std::errc() || parsed.ptr != item.data() + item.size() || !std::isfinite(value))
        throw ParseError(line, name + " argument " + std::to_string(values.size() + 1) + " '" + std::string(item) +
                                   "' is neither a number nor an R parameter or variable the program has set: give its value or "
                                   "set it before the call");
    }
    values.push_back(value);
    if (comma >= text.size()) return values;
    from = comma + 1;
  }
}

// Siemens SINUMERIK 840D sl Cycles Programming Manual, "Drilling cycles": CYCLE81(RTP, RFP, SDIS, DP, DPR) and
// the others with these first five: rapid to the reference plane RFP plus the safety distance SDIS, in to the
// final depth DP (or DPR below RFP), back to the retraction plane RTP. CYCLE82 dwells DTB s; CYCLE83 pecks
// (FDEP or FDPR the first depth, each next one DAM less, down to DAM; VARI 1 back to RFP + SDIS after each, 0
// breaking the chip); CYCLE84 taps at SST times the pitch PIT (at F without PIT) and
// back; CYCLE85 and
// CYCLE89 feed out to RFP + SDIS; CYCLE86, 87, 88 come out at rapid (87's and 88's operator stop not timed).
void Interpreter::siemensDrilling(int number, const std::string& arguments) {
  const std::string name = "CYCLE" + std::to_string(number);
  std::vector<double> a = siemensCycleArguments(arguments, name, lineNumber_);
  a.resize(16, std::numeric_limits<double>::quiet_NaN());
  auto given = [&](int i) { return std::isfinite(a[static_cast<size_t>(i)]); };
  if (!given(0) || !given(1) || (!given(3) && !given(4)))
    throw ParseError(lineNumber_, name + " needs RTP, RFP and DP (or DPR): the retraction and reference planes and "
                                         "the final depth");
  const double rtp = a[0] * unit_, rfp = a[1] * unit_, sdis = given(2) ? a[2] * unit_ : 0.0;
  const double frameZ = frame().z();
  cycleClear_ = rtp + frameZ;
  cycleR_ = rfp + sdis + frameZ;
  cycleZ_ = (given(3) ? a[3] * unit_ : rfp - std::abs(a[4]) * unit_) + frameZ;
  cycleP_ = 0.0;
  const int dwellArgument = number == 82 || number == 85 || number == 86 || number == 88 || number == 89 ? 5
                            : number == 83                                                             ? 8
                                                                                                       : -1;
  if (dwellArgument > 0 && given(dwellArgument)) cycleP_ = std::abs(a[static_cast<size_t>(dwellArgument)]);
  int as = number;
  const CycleModes borrowed(*this);
  if (number == 83) {
    const double first = given(6) ? std::abs(a[6]) * unit_ : given(5) ? rfp + frameZ - (a[5] * unit_ + frameZ) : 0.0;
    cycleQ_ = first > 0.0 ? first : (cycleR_ - cycleZ_);
    as = given(11) && a[11] == 0.0 ? 73 : 83;
  } else if (number == 84) {
    // At SST (or S) times the pitch PIT; a call without PIT (posts leave it out) taps at the programmed F
    const double pitch = given(8) ? std::abs(a[8]) * unit_ : 0.0;
    const double speed = given(10) ? std::abs(a[10]) : spindle_;
    if (pitch > 0.0 && !(speed > 0.0))
      throw ParseError(lineNumber_, "CYCLE84 taps at S0: program the spindle speed (SST, argument 11, or S)");
    if (pitch > 0.0) feed_ = speed * pitch / 60.0;
  } else if (number == 87 || number == 88) {
    as = 86;
  }
  cycle_ = as;
  pathMode_ = PathMode::ExactStop;
  cycleDegression_ = number == 83 && given(7) ? std::abs(a[7]) * unit_ : 0.0;
  cycleBlocks(LineWords{}, false);
  cycleDegression_ = 0.0;
}

bool Interpreter::homeBlocks(const LineWords& w, Block& block) {
  if (!w.anyAxis()) return false;  // G28 alone: LinuxCNC moves all axes home, a Fanuc none; neither is timed
  Eigen::Vector3d through = position_;
  for (int a = 0; a < 3; ++a)
    if (w.hasAxis[a]) through[a] = absolute_ ? fromProgram(a, w.axis[a])[a] : position_[a] + w.axis[a] * unit_;
  Eigen::Vector3d home = through;
  for (int a = 0; a < 3; ++a)
    if (w.hasAxis[a]) home[a] = -options_.conventions.workOffset[a];  // machine zero, the reference point
  queueMove(through, true);
  queueMove(home, true);
  return popQueued(block);
}

void Interpreter::setOffset(const LineWords& w) {
  if (w.offsetSetting == 92) {  // the current position becomes the programmed one
    for (int a = 0; a < 3; ++a)
      if (w.hasAxis[a]) shift_[a] = position_[a] - (workOffsets_[static_cast<size_t>(workOffset_)][a] -
                                                    options_.conventions.workOffset[a]) - w.axis[a] * unit_;
    return;
  }
  const long l = std::lround(w.lWord), p = std::lround(w.pWord);
  if (w.hasL && (l == 1 || l == 10 || l == 11)) return unknown("G10 L" + number(w.lWord));  // tool data: no move here
  if (!w.hasL || (l != 2 && l != 20))
    return unknownMotion("G10 L" + number(w.lWord), "an offset table the simulator does not keep (G10 L2 and L20 are read)");
  if (!w.hasP || p < 0 || p > 9)
    throw ParseError(lineNumber_, "G10 L" + std::to_string(l) + " needs P0 to P9: the work offset to set (P0 the active)");
  const size_t entry = static_cast<size_t>(p == 0 ? workOffset_ : p);
  for (int a = 0; a < 3; ++a) {
    if (!w.hasAxis[a]) continue;
    const double value = w.axis[a] * unit_;
    // L2: the offset itself (machine coordinates); L20: so that the tool is at the value in that frame
    workOffsets_[entry][a] = l == 2 ? value : position_[a] + options_.conventions.workOffset[a] - shift_[a] - value;
  }
}

bool Interpreter::rigidTapBlocks(const LineWords& w, Block& block) {
  if (!w.hasOffset[2] || !(w.offset[2] > 0.0))
    throw ParseError(lineNumber_, "G33.1 needs K > 0: the thread's pitch (distance per spindle turn)");
  if (!(spindle_ > 0.0)) throw ParseError(lineNumber_, "G33.1 taps at S0: program the spindle speed (S) before it");
  if (!w.anyAxis()) throw ParseError(lineNumber_, "G33.1 needs the tap's end point (Z)");
  if (!absolute_) throw ParseError(lineNumber_, "G33.1 in G91: rigid tapping is read in absolute coordinates (G90)");
  Eigen::Vector3d bottom = position_;
  for (int a = 0; a < 3; ++a)
    if (w.hasAxis[a]) bottom[a] = fromProgram(a, w.axis[a])[a];
  const Eigen::Vector3d start = position_;
  const double feed = feed_;
  feed_ = spindle_ * w.offset[2] * unit_ / 60.0;  // the axis follows the spindle: pitch per turn
  for (const Eigen::Vector3d& target : {bottom, start}) queueMove(target, false);
  feed_ = feed;
  return popQueued(block);
}

void Interpreter::unknownMotion(std::string_view word, std::string_view what) {
  if (!options_.skipUnknownMotion && !options_.refuseUnknownWords)
    throw ParseError(lineNumber_, "'" + std::string(word) + "' (" + std::string(what) + ") would move the machine in a "
                                 "way the simulator does not read, so the program stops here; to time it without "
                                 "that word, skip unknown words (hsm-feedsim --skip-unknown, skip_unknown=True)");
  unknown(word);
}

void Interpreter::unknown(std::string_view word) {
  if (options_.refuseUnknownWords)
    throw ParseError(lineNumber_, "'" + std::string(word) + "' is not understood: remove it, or let unknown "
                                 "words be skipped (refuse_unknown_words off)");
  ++stats_.unknownWords;
  auto it = stats_.unknownWordCounts.find(std::string(word));
  if (it != stats_.unknownWordCounts.end()) {
    ++it->second;
  } else if (stats_.unknownWordCounts.size() < 50) {
    stats_.unknownWordCounts.emplace(std::string(word), 1);
  }
}

void Interpreter::gWord(const Word& w, LineWords& words) {
  const long code = std::lround(w.value * 10.0);
  if (std::abs(w.value * 10.0 - code) > 1e-6) return unknown(w.text);
  switch (code) {
    case 0: case 10: case 20: case 30: words.newMotion = int(code / 10); break;
    case 40: words.dwell = true; break;
    case 90: words.exactStopHere = true; break;
    case 170: case 180: case 190: plane_ = int(code / 10); break;
    // G20 / G21; the 840D's G700 / G710 (lengths and feeds) and G70 / G71 (lengths only: F stays in the basic
    // system, Programming Manual Fundamentals, "Inch or metric dimensions")
    case 200: case 7000: words.units = words.feedUnits = 25.4; break;
    case 210: case 7100: words.units = words.feedUnits = 1.0; break;
    case 700: case 710:
      words.units = code == 700 ? 25.4 : 1.0;
      if (options_.conventions.dialect != Dialect::Siemens840D) words.feedUnits = words.units;
      break;
    case 900: absolute_ = true; break;
    case 910: absolute_ = false; break;
    case 901: arcCentreAbsolute_ = true; break;
    case 911: arcCentreAbsolute_ = false; break;
    case 600: case 610: case 611: pathMode_ = PathMode::ExactStop; break;
    case 640: words.g64 = true; break;
    case 6410: case 6420: case 6430: case 6440: case 6450:
      pathMode_ = PathMode::Rounding;
      tolerance_ = roundingTolerance_;
      break;
    case 930: inverseTime_ = true; break;
    case 940: inverseTime_ = false; break;
    case 730: case 810: case 820: case 830: case 840: case 850: case 860: case 890: words.cycle = int(code / 10); break;
    case 740: case 760: case 870: case 880:  // Fanuc's reverse tapping, fine boring, back boring, boring by hand
      if (isFanucFamily(options_.conventions.dialect) || code == 880) {
        words.cycle = int(code / 10);
      } else {
        unknownMotion(w.text, "a canned cycle this dialect does not have as read here");
      }
      break;
    case 800: words.cancelCycle = true; break;
    case 331: words.rigidTap = true; break;
    case 980: retractToR_ = false; break;
    case 990: retractToR_ = true; break;
    case 280: case 300: words.home = int(code / 10); break;
    case 530: words.machineCoordinates = true; break;
    case 540: case 550: case 560: case 570: case 580: case 590: workOffset_ = int(code / 10) - 53; break;
    case 591: case 592: case 593: workOffset_ = int(code - 584); break;  // G59.1 … G59.3: entries 7 … 9
    case 100: words.offsetSetting = 10; break;
    case 920: words.offsetSetting = 92; break;
    case 921: case 922: shift_.setZero(); break;  // G92.1 cancels, G92.2 suspends (not restored: G92.3 unread)
    case 434: case 2340: toolTip_ = true; break;  // Fanuc G43.4, Haas G234: tool centre point
    case 490: toolTip_ = false; break;
    case 50: case 51: case 80: case 1870: words.lookAhead = int(code); break;
    // Accepted without effect on the simulated motion: cutter and length compensation (the path is timed as
    // programmed, not offset by the tool's radius), extended work offsets (G54.1 P: taken as G54), cancels of
    // scaling, mirror, rotation and polar coordinates, exact-stop windows, 840D frame suppression.
    case 400: case 410: case 420: case 430: case 431: case 1430: case 541: case 500: case 501: case 690: case 150:
    case 6010: case 6020: case 6030: case 5000: case 5010: case 1030: case 1000:
      break;
    case 160: unknownMotion(w.text, "polar coordinates"); break;
    default:
      // The 840D's settable zero offsets G505…G599 (and G500 off), taken as the program's work offset
      if (options_.conventions.dialect == Dialect::Siemens840D && code >= 5000 && code <= 5990 && code % 10 == 0) break;
      unknownMotion(w.text, "a G code the simulator does not know");
      break;
    case 680: case 682: case 531: case 681: unknownMotion(w.text, "a rotated or tilted working plane (read: G43.4, G234)"); break;
  }
}

void Interpreter::mWord(const Word& w) {
  const long code = std::lround(w.value);
  if (code == 6) ++stats_.toolChanges;
  const bool known = code == 0 || code == 1 || code == 2 || code == 3 || code == 4 || code == 5 || code == 6 ||
                     code == 7 || code == 8 || code == 9 || code == 30 || code == 17;
  if (!known) unknown(w.text);
}

void Interpreter::keyword(const Keyword& k, LineWords& words) {
  const std::string_view name = k.name;
  if (name == "SOFT") {
    jerkLimited_ = 1;
  } else if (name == "BRISK") {
    jerkLimited_ = 0;
  } else if (name == "CR" && k.hasValue) {
    words.radiusWord = k.value;
    words.hasRadius = true;
  } else if ((name == "ADIS" || name == "ADISPOS") && k.hasValue) {
    roundingTolerance_ = k.value * unit_;
    if (pathMode_ == PathMode::Rounding) tolerance_ = roundingTolerance_;
  } else if (name == "T") {
    ++stats_.toolChanges;  // T="BALL4": a tool called by name
  } else if (name == "MSG") {
    // operator messages
  } else if (name == "CYCLE832" && k.call) {
    cycle832(k.arguments);
  } else if (name.size() == 7 && name.substr(0, 6) == "CYCLE8" && name[6] >= '1' && name[6] <= '9' && k.call) {
    words.siemensCycle = 80 + (name[6] - '0');
    words.siemensArguments = k.arguments;
  } else if (name == "CYCLE800" && k.call) {
    cycle800(std::string(k.arguments));
  } else if (name.size() == 3 && (name.substr(0, 2) == "IC" || name.substr(0, 2) == "AC") && k.hasValue &&
             std::string_view("XYZABC").find(name[2]) != std::string_view::npos) {
    // X=IC(…), X=AC(…), rewritten by the 840D's language as ICX=…, ACX=…
    const size_t axis = std::string_view("XYZABC").find(name[2]);
    words.axisMode[axis] = name[0] == 'A' ? 1 : 2;
    if (axis < 3) {
      if (words.hasAxis[axis]) throw ParseError(lineNumber_, std::string("axis ") + name[2] + " given twice");
      words.hasAxis[axis] = true;
      words.axis[axis] = k.value;
    } else {
      rotaryWord(static_cast<int>(axis - 3), k.value, name.substr(2), words);
    }
  } else if (name == "CIP") {
    words.newMotion = 4;
  } else if ((name == "I1" || name == "J1" || name == "K1") && k.hasValue) {
    words.hasThrough[name[0] - 'I'] = true;
    words.through[name[0] - 'I'] = k.value;
  } else if (name == "MCALL") {
    words.mcall = true;
  } else if (name == "SUPA") {
    words.machineCoordinates = true;  // this block in machine coordinates, every frame suppressed (as G53 here)
  } else if (name == "FNORM" || name == "SETMS" || name == "SBLOF" || name == "SBLON") {
    // feed per minute (G94's), the master spindle, single-block suppression: nothing the motion shows
  } else if ((name == "A" || name == "B" || name == "C") && k.hasValue) {
    rotaryWord(name[0] - 'A', k.value, name, words);
  } else if ((name == "A3" || name == "B3" || name == "C3") && k.hasValue) {
    const int a = name[0] - 'A';
    if (words.hasVector[a]) throw ParseError(lineNumber_, std::string(name) + " given twice");
    words.hasVector[a] = true;
    words.vector[a] = k.value;
  } else if (name == "A3" || name == "B3" || name == "C3") {
    throw ParseError(lineNumber_, std::string(name) + "= needs a number: an orientation vector's component");
  } else if (name == "TRAORI") {
    toolTip_ = true;
  } else if (name == "TRAFOOF") {
    toolTip_ = false;
  } else if (name == "ORIMKS" || name == "ORIAXES") {
    orientationByAxes_ = true;
  } else if (name == "ORIWKS" || name == "ORIVECT") {
    orientationByAxes_ = false;
  } else if (name == "COMPCAD" || name == "COMPCURV" || name == "COMPSURF") {
    compressor_ = true;
  } else if (name == "COMPOF") {
    compressor_ = false;
  } else if (name == "COMPON" || name == "FFWON" ||
             name == "FFWOF" || name == "UPATH" || name == "SPATH" ||
             name == "DYNNORM" || name == "DYNFINISH" || name == "DYNSEMIFIN" || name == "DYNROUGH") {
    // compressor, feed-forward, dynamic-response groups: no effect on this model
  } else if (options_.conventions.dialect == Dialect::Siemens840D && movesUnseen(name) != nullptr) {
    unknownMotion(name, movesUnseen(name));
  } else {
    unknown(name);
  }
}

void Interpreter::rotaryWord(int axis, double value, std::string_view text, LineWords& words) {
  if (words.hasRotary[axis]) throw ParseError(lineNumber_, "rotary axis " + std::string(text.substr(0, 1)) + " given twice");
  words.hasRotary[axis] = true;
  words.rotary[axis] = value;  // degrees: G20/G21 do not scale angles
}

Eigen::Vector3d Interpreter::orientationTarget(const LineWords& w) const {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // as on the 840D: a component not written is 0
  for (int a = 0; a < 3; ++a)
    if (w.hasVector[a]) v[a] = w.vector[a];
  const double n = v.norm();
  if (!(n > 1e-9))
    throw ParseError(lineNumber_, "orientation vector A3 B3 C3 = (" + number(v.x()) + ", " + number(v.y()) + ", " +
                                      number(v.z()) + ") has no length: give the tool axis's direction");
  return v / n;
}

void Interpreter::cycle832(std::string_view arguments) {
  const auto comma = arguments.find(',');
  std::string_view first = arguments.substr(0, comma);
  while (!first.empty() && (first.front() == ' ')) first.remove_prefix(1);
  double value = 0.0;
  if (first.empty()) {
    pathMode_ = PathMode::Continuous;
    jerkLimited_ = 0;
    compressor_ = false;
    return;
  }
  const auto parsed =
      fast_float::from_chars(first.data(), first.data() + first.size(), value, fast_float::chars_format::fixed);
  if (parsed.ec != std::errc() || value < 0.0) return unknown("CYCLE832(" + std::string(first) + ")");
  if (value == 0.0) {
    pathMode_ = PathMode::Continuous;
    jerkLimited_ = 0;
    compressor_ = false;
    return;
  }
  roundingTolerance_ = value * unit_;
  pathMode_ = PathMode::Rounding;
  tolerance_ = roundingTolerance_;
  jerkLimited_ = 1;
  compressor_ = true;  // the cycle switches the compressor on with the rounding (COMPCAD)
}

void Interpreter::arc(Block& block, const LineWords& words) {
  const double* offset = words.offset;
  const bool* hasOffset = words.hasOffset;
  const double radiusWord = words.radiusWord;
  const bool hasRadius = words.hasRadius;
  static constexpr int kPlaneAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};  // G17 XY/Z, G18 ZX/Y, G19 YZ/X
  const int* axes = kPlaneAxes[plane_ == 17 ? 0 : plane_ == 18 ? 1 : 2];
  const int u = axes[0], v = axes[1], n = axes[2];
  block.normal = Eigen::Vector3d::Unit(n);
  const Eigen::Vector3d& s = block.start;
  const Eigen::Vector3d& e = block.end;
  Eigen::Vector3d centre = s;
  if (hasRadius && !(hasOffset[u] || hasOffset[v])) {
    const double r = std::abs(radiusWord) * unit_;
    const Eigen::Vector2d a(s[u], s[v]), b(e[u], e[v]);
    const Eigen::Vector2d chord = b - a;
    const double d = chord.norm();
    if (r <= 0.0 || d == 0.0)
      throw ParseError(lineNumber_, "an arc by radius needs R > 0 and an end point away from the start");
    if (d > 2.0 * r * (1.0 + 1e-9) + 1e-9)
      throw ParseError(lineNumber_, "arc radius " + std::to_string(r) + " mm is less than half the chord (" +
                                       std::to_string(d / 2) + " mm): no such arc");
    const double h = std::sqrt(std::max(0.0, r * r - d * d / 4.0));
    const Eigen::Vector2d left(-chord.y() / d, chord.x() / d);  // chord turned +90° about the normal
    // Counter-clockwise short arc: centre on the left of the chord; clockwise or R < 0 flips it.
    const bool clockwise = block.motion == Motion::ArcClockwise;
    const double side = (clockwise ? -1.0 : 1.0) * (radiusWord < 0 ? -1.0 : 1.0);
    const Eigen::Vector2d c = 0.5 * (a + b) + side * h * left;
    centre[u] = c.x();
    centre[v] = c.y();
  } else {
    if (!(hasOffset[u] || hasOffset[v]))
      throw ParseError(lineNumber_, "arc without centre: give I/J/K (or R / CR=) for the active plane G" +
                                       std::to_string(plane_));
    for (int a : {u, v}) centre[a] = arcCentreAbsolute_ ? offset[a] * unit_ + frame()[a] : s[a] + offset[a] * unit_;
  }
  centre[n] = s[n];
  const Eigen::Vector3d rs = s - centre, re = Eigen::Vector3d(e[u] - centre[u], e[v] - centre[v], 0.0);
  const double r0 = std::hypot(rs[u], rs[v]), r1 = re.head<2>().norm();
  if (r0 <= 1e-9) throw ParseError(lineNumber_, "arc radius is zero: the centre is on the start point");
  if (std::abs(r1 - r0) > options_.arcRadiusTolerance + 1e-3 * r0)
    throw ParseError(lineNumber_, "arc end point is not on the circle: its radius is " + std::to_string(r1) +
                                     " mm, the start's " + std::to_string(r0) + " mm");
  double angle = std::atan2(rs[u] * re.y() - rs[v] * re.x(), rs[u] * re.x() + rs[v] * re.y());
  const bool full = std::hypot(e[u] - s[u], e[v] - s[v]) < 1e-9;
  if (block.motion == Motion::ArcCounterClockwise) {
    if (angle <= 0.0 || full) angle += 2.0 * M_PI;
  } else {
    if (angle >= 0.0 || full) angle -= 2.0 * M_PI;
  }
  if (full) angle = block.motion == Motion::ArcCounterClockwise ? 2.0 * M_PI : -2.0 * M_PI;
  block.center = centre;
  block.radius = r0;
  block.sweep = angle;
}

// SINUMERIK 840D sl Programming Manual Fundamentals, "Circular interpolation with intermediate and end points
// (CIP)": the circle through the start, the intermediate point (I1= J1= K1=: in G90 where it is, in G91 from the
// start; a coordinate not given is the start's) and the end, run from the start through the intermediate point.
void Interpreter::arcThrough(Block& block, const LineWords& w) const {
  if (!(w.hasThrough[0] || w.hasThrough[1] || w.hasThrough[2]))
    throw ParseError(lineNumber_, "CIP needs its intermediate point: I1= J1= K1= (the point the arc passes through)");
  Eigen::Vector3d middle = block.start;
  for (int a = 0; a < 3; ++a)
    if (w.hasThrough[a]) middle[a] = absolute_ ? w.through[a] * unit_ + frame()[a] : block.start[a] + w.through[a] * unit_;
  const Eigen::Vector3d u = middle - block.start, v = block.end - block.start;
  const Eigen::Vector3d n = u.cross(v);
  if (n.norm() <= 1e-9 * std::max(1e-9, u.norm() * v.norm()))
    throw ParseError(lineNumber_, "CIP: the start, the intermediate point and the end are on one line (or two of "
                                  "them are one point): no circle passes through them");
  const Eigen::Vector3d centre = block.start + (u.squaredNorm() * v - v.squaredNorm() * u).cross(n) / (2.0 * n.squaredNorm());
  const Eigen::Vector3d normal = n.normalized();
  const Eigen::Vector3d rs = block.start - centre, re = block.end - centre;
  double sweep = std::atan2(normal.dot(rs.cross(re)), rs.dot(re));
  if (sweep <= 0.0) sweep += 2.0 * M_PI;  // from the start through the intermediate point: counter-clockwise about n
  block.motion = Motion::ArcCounterClockwise;
  block.center = centre;
  block.normal = normal;
  block.radius = rs.norm();
  block.sweep = sweep;
}

}  // namespace hsm::kinematics::detail
