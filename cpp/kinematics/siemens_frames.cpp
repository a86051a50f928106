// The 840D's frames (the Interpreter's, internal): the programmable frame (TRANS, ROT, SCALE, MIRROR and their
// additive forms), CYCLE800's swivel, and how the blocks made in their coordinates are turned out.
#include "kinematics/gcode_interpreter.hpp"

#include "common/text.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace hsm::kinematics::detail {

namespace {
constexpr double kDegree = M_PI / 180.0;

Eigen::Matrix3d turn(int axis, double degrees) {
  return Eigen::AngleAxisd(degrees * kDegree, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

Eigen::Matrix3d rotation(const double (&degrees)[3]) {  // RPY: about Z, then the new Y, then the newest X
  return turn(2, degrees[2]) * turn(1, degrees[1]) * turn(0, degrees[0]);
}
}  // namespace

bool isSiemensFrameKeyword(std::string_view name) {
  return name == "TRANS" || name == "ATRANS" || name == "ROT" || name == "AROT" || name == "SCALE" ||
         name == "ASCALE" || name == "MIRROR" || name == "AMIRROR";
}

Eigen::Vector3d Interpreter::frame() const {
  const Eigen::Vector3d origin = workOffsets_[static_cast<size_t>(workOffset_)] - options_.conventions.workOffset +
                                 shift_ + swivelShift_ + swivelTurn_ * programmable_;
  return rotated_ ? Eigen::Vector3d(inverseLinear_ * origin) : origin;
}

void Interpreter::applyFrame() {
  const Eigen::Matrix3d linear = swivelTurn_ * programmableLinear_;
  if (!linear.allFinite() || std::abs(linear.determinant()) < 1e-12)
    throw ParseError(lineNumber_, "the frame would flatten the coordinates (a scale of 0): give every factor a size");
  const Eigen::Vector3d here = rotated_ ? Eigen::Vector3d(linear_ * position_) : position_;
  linear_ = linear;
  rotated_ = !linear.isIdentity(0.0);
  inverseLinear_ = linear.inverse();
  position_ = rotated_ ? Eigen::Vector3d(inverseLinear_ * here) : here;  // the tool stays where it is
}

void Interpreter::toPositions(Block& block) const {
  if (rotated_) {
    block.start = linear_ * block.start;
    block.end = linear_ * block.end;
    if (block.orientationEnd.squaredNorm() > 0.0) block.orientationEnd = (linear_ * block.orientationEnd).normalized();
    if (block.isArc()) {
      // A circle stays one when the frame scales its plane alike in every direction (and keeps it square)
      const Eigen::Vector3d u = block.normal.unitOrthogonal(), v = block.normal.cross(u);
      const Eigen::Vector3d lu = linear_ * u, lv = linear_ * v;
      const double su = lu.norm(), sv = lv.norm();
      if (std::abs(su - sv) > 1e-9 * su || std::abs(lu.dot(lv)) > 1e-9 * su * sv)
        throw ParseError(block.line, "an arc under a SCALE that differs between the axes of its plane is an "
                                     "ellipse, which the 840D does not cut either: scale both axes alike");
      block.center = linear_ * block.center;
      block.normal = lu.cross(lv).normalized();  // a mirror turns the arc the other way about the normal
      block.radius *= su;
    }
  }
  if (swivelled_) {  // the tool tip in the workpiece, the tool along the swivelled Z
    block.toolTip = true;
    block.rotary = true;
    block.orientationVectors = true;
    block.orientationByAxes = false;
    block.orientationEnd = swivelAxis_;
  }
}

Eigen::Vector3d Interpreter::machineTarget(const LineWords& w) const {
  Eigen::Vector3d machine = rotated_ ? Eigen::Vector3d(linear_ * position_) : position_;
  for (int a = 0; a < 3; ++a)
    if (w.hasAxis[a]) machine[a] = w.axis[a] * unit_ - options_.conventions.workOffset[a];
  return rotated_ ? Eigen::Vector3d(inverseLinear_ * machine) : machine;
}

// SINUMERIK 840D sl Programming Manual Fundamentals, "Coordinate transformations (frames)": TRANS, ROT, SCALE
// and MIRROR replace the whole programmable frame (alone, they clear it), ATRANS, AROT, ASCALE and AMIRROR add to
// it in the coordinates it has made. ROT X Y Z turns about Z, then the new Y, then the newest X (the RPY order
// of FRAME_ANGLE_INPUT_MODE 1); ROT RPL= in the working plane. SCALE multiplies (an arc under a scale that
// differs in its plane is refused), MIRROR X0 reverses X. A frame instruction stands in a block of its own.
void Interpreter::programmableFrame(std::string_view name, const Line& line) {
  double values[3] = {0, 0, 0};
  bool has[3] = {false, false, false};
  double plane = 0.0;
  bool hasPlane = false;
  auto alone = [&](std::string_view other) {
    throw ParseError(lineNumber_, std::string(name) + " with '" + std::string(other) + "': a frame instruction stands "
                                  "in a block of its own with its axes (X Y Z, RPL=): move the rest to its own block");
  };
  for (int i = 0; i < line.wordCount; ++i) {
    const Word& w = line.words[static_cast<size_t>(i)];
    if (w.letter >= 'X' && w.letter <= 'Z') {
      values[w.letter - 'X'] = w.value;
      has[w.letter - 'X'] = true;
    } else if (w.letter != 'N') {
      alone(w.text);
    }
  }
  for (const Keyword& k : line.keywords) {
    if (k.name == "RPL" && k.hasValue) {
      plane = k.value;
      hasPlane = true;
    } else if (!isSiemensFrameKeyword(k.name)) {
      alone(k.name);
    }
  }
  const bool additive = name[0] == 'A';
  const std::string_view kind = additive ? name.substr(1) : name;
  Eigen::Matrix3d change = Eigen::Matrix3d::Identity();
  if (!additive && !has[0] && !has[1] && !has[2] && !hasPlane) {  // TRANS, ROT, SCALE, MIRROR alone: cleared
    programmable_.setZero();
  } else if (kind == "TRANS") {
    const Eigen::Vector3d shift = Eigen::Vector3d(values[0], values[1], values[2]) * unit_;
    if (additive) {
      programmable_ += programmableLinear_ * shift;
      return;
    }
    programmable_ = shift;
  } else if (kind == "ROT") {
    if (hasPlane && (has[0] || has[1] || has[2]))
      throw ParseError(lineNumber_, std::string(name) + ": RPL= turns in the plane, X Y Z in space: give one or the other");
    if (hasPlane) values[plane_ == 17 ? 2 : plane_ == 18 ? 1 : 0] = plane;
    change = rotation(values);
  } else if (kind == "SCALE") {
    for (int a = 0; a < 3; ++a) change(a, a) = has[a] ? values[a] : 1.0;
  } else if (kind == "MIRROR") {
    for (int a = 0; a < 3; ++a) change(a, a) = has[a] ? -1.0 : 1.0;
  }
  if (additive) {
    programmableLinear_ = programmableLinear_ * change;
  } else {
    if (kind != "TRANS") programmable_.setZero();
    programmableLinear_ = change;
  }
  applyFrame();
}

// SINUMERIK 840D sl Cycles Programming Manual, "Swiveling - CYCLE800": CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0,
// _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR, _FR_I, _DMODE). The new plane (_ST's units 0; 1 adds to the last one) is
// the reference point X0 Y0 Z0, turned axis by axis (_MODE's two-bit fields from its lowest: the first, second
// and third axis, 1 X 2 Y 3 Z, turned by _A, _B, _C in that order, each about the axes the last one left), then
// shifted by X1 Y1 Z1; the programmable frame is cleared. The rotary axes turn the tool along the plane's Z at
// rapid, the linear axes standing; the program then gives the tool tip in the plane. CYCLE800() takes the plane
// back (the rotary axes stay until a move sets them). Not read, and named as unseen motion: the solid-angle,
// projection-angle and direct modes (_MODE's top bits). Not timed: the retract before the swivel (_FR: the
// machine file has no travel limits); _DIR is left to the machine's nearest solution.
void Interpreter::cycle800(const std::string& arguments) {
  std::vector<double> a = siemensCycleArguments(arguments, "CYCLE800", lineNumber_);
  const bool any = std::any_of(a.begin(), a.end(), [](double v) { return !std::isnan(v); });
  a.resize(16, std::numeric_limits<double>::quiet_NaN());
  auto value = [&](size_t i) { return std::isnan(a[i]) ? 0.0 : a[i]; };
  if (!any) {  // CYCLE800(): the plane taken back
    swivelTurn_.setIdentity();
    swivelShift_.setZero();
    swivelAxis_ = Eigen::Vector3d::UnitZ();
    swivelled_ = false;
    applyFrame();
    return;
  }
  const long mode = std::lround(value(3));
  if (!(value(3) >= 0.0 && value(3) <= 255.0 && value(3) == std::floor(value(3))))
    throw ParseError(lineNumber_, "CYCLE800 _MODE " + number(value(3)) + " is not a swivel mode: a whole number from 0 "
                                  "to 255 (57: axis by axis, X then Y then Z)");
  if ((mode >> 6) != 0)
    return unknownMotion("CYCLE800", "a swivel in solid angles, projection angles or rotary axis positions (read: "
                                     "axis by axis, _MODE below 64)");
  Eigen::Matrix3d turned = Eigen::Matrix3d::Identity();
  for (int step = 0; step < 3; ++step) {
    const long axis = (mode >> (2 * step)) & 3;
    if (axis != 0) turned = turned * turn(static_cast<int>(axis - 1), value(7 + static_cast<size_t>(step)));
  }
  const Eigen::Vector3d before(value(4), value(5), value(6)), after(value(10), value(11), value(12));
  const Eigen::Vector3d shift = (before + turned * after) * unit_;
  const bool additive = std::lround(value(2)) % 10 == 1;
  if (additive) {
    swivelShift_ += swivelTurn_ * shift;
    swivelTurn_ = swivelTurn_ * turned;
  } else {
    swivelShift_ = shift;
    swivelTurn_ = turned;
  }
  programmable_.setZero();
  programmableLinear_.setIdentity();
  applyFrame();
  const Eigen::Vector3d axis = swivelTurn_.col(2);
  swivelled_ = (axis - Eigen::Vector3d::UnitZ()).norm() > 1e-12;  // a turn about Z alone is a frame, no swivel
  if (!swivelled_ || (swivelAxis_ - axis).norm() < 1e-12) {
    swivelAxis_ = axis;
    return;
  }
  swivelAxis_ = axis;
  // the turn of the rotary axes: the tool's axis to the plane's Z where the machine's linear axes stand
  Block& move = swivelMove_;
  move = Block{};
  move.start = move.end = rotated_ ? Eigen::Vector3d(linear_ * position_) : position_;
  move.motion = Motion::Rapid;
  move.line = lineNumber_;
  move.pathMode = PathMode::ExactStop;
  move.rotary = true;
  move.orientationVectors = true;
  move.orientationEnd = axis;
  move.jerkLimited = jerkLimited_;
  rotarySeen_ = true;
  swivelMovePending_ = true;
}

}  // namespace hsm::kinematics::detail
