#include "kinematics/five_axis_motion.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hsm::kinematics {

namespace {
constexpr double kDegreesPerPiece = 1.0;  // rotary motion per piece: the rates' change within one stays small
constexpr double kArcDegreesPerPiece = 5.0;

// The unit vector a fraction t of the way from a to b on their great circle.
Eigen::Vector3d slerp(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) {
  const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  if (angle < 1e-12) return a;
  const double s = std::sin(angle);
  if (s < 1e-9) {  // opposite vectors: the great circle is not defined; turn about any normal to a
    Eigen::Vector3d n = a.unitOrthogonal();
    return Eigen::AngleAxisd(t * angle, n) * a;
  }
  return (std::sin((1.0 - t) * angle) * a + std::sin(t * angle) * b) / s;
}

double degreesBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
}
}  // namespace

const char* speedLimitName(SpeedLimit limit) {
  static const char* names[kSpeedLimitCount] = {"F", "X", "Y", "Z", "A", "B", "C", "curvature", "block rate"};
  return names[static_cast<int>(limit)];
}

void FiveAxisCutter::programPiece(const Block& block,
                                  const std::function<void(const Block&, const JointMotion&)>& piece) {
  const MachineModel& m = machine_;
  const RotaryAngles startAngles = previous_;
  JointMotion joint;
  joint.active = true;
  joint.start = jointsAt(block, 0.0);
  previous_ = startAngles;
  joint.end = jointsAt(block, 1.0);
  // X Y Z and the angles as the program gives them (tip, A B C), each linear along the block
  JointVector from, to;
  from << block.start, fromAngles_[0], fromAngles_[1];
  to << block.end, toAngles_[0], toAngles_[1];
  joint.tipLength = (block.end - block.start).norm();
  joint.rotaryOnly = joint.tipLength < 1e-6;
  joint.pathLength = joint.rotaryOnly ? (to.tail<2>() - from.tail<2>()).norm() : joint.tipLength;
  if (joint.pathLength > 0.0) {
    joint.rate = (to - from) / joint.pathLength;
    Block b = block;
    if (!(block.toolTip || m.toolTipProgrammed)) {  // the program gives the machine's axes: report the tip
      b.start = forwardKinematics(m, {joint.start.head<3>(), {joint.start[3], joint.start[4]}}).tip;
      b.end = forwardKinematics(m, {joint.end.head<3>(), {joint.end[3], joint.end[4]}}).tip;
    }
    if (block.inverseTime) b.feed = joint.pathLength * block.feed;
    b.rateLength = joint.pathLength;
    piece(b, joint);
  }
  previous_ = toAngles_;
  programmed_ = block.rotaryEnd;
  orientation_ = Eigen::Vector3d::Zero();
  endKnown_ = false;
}

JointVector FiveAxisCutter::jointsAt(const Block& b, double lambda) {
  const MachineModel& m = machine_;
  const Eigen::Vector3d point = b.isArc() ? b.pointAt(lambda * b.length()) : b.start + lambda * (b.end - b.start);
  RotaryAngles angles = previous_;
  if (b.orientationVectors && !b.orientationByAxes) {
    const Eigen::Vector3d& from = orientation_;
    const Eigen::Vector3d axis = slerp(from, b.orientationEnd, lambda);
    ToolPose pose{point, axis};
    const InverseResult inverse = inverseKinematics(m, pose, previous_);
    angles = inverse.position.angles;
  } else {  // the rotary axes interpolate linearly
    for (size_t i = 0; i < m.rotaryAxes.size(); ++i)
      angles[i] = fromAngles_[i] + lambda * (toAngles_[i] - fromAngles_[i]);
  }
  const bool tip = b.toolTip || m.toolTipProgrammed;
  JointVector q;
  q.head<3>() = tip ? linearAxesFor(m, point, angles) : point;
  q[3] = angles[0];
  q[4] = angles[1];
  previous_ = angles;
  return q;
}

void FiveAxisCutter::sample(const Block& block, const RotaryAngles& startAngles, int& pieces,
                            std::vector<JointVector>& q) {
  for (int attempt = 0;; ++attempt) {
    // Near a singularity the angles swing more than the orientation turns: cut finer until no piece turns
    // an axis more than 2°, or the bound is reached.
    previous_ = startAngles;
    q.assign(1, startJoints(block, startAngles));
    double widest = 0.0;
    for (int i = 1; i <= pieces; ++i) {
      q.push_back(jointsAt(block, double(i) / pieces));
      widest = std::max(widest, (q[i].tail<2>() - q[i - 1].tail<2>()).cwiseAbs().maxCoeff());
    }
    if (widest <= 2.0 * kDegreesPerPiece || pieces >= kMaxPiecesPerBlock || attempt >= 4) break;
    pieces = std::min(kMaxPiecesPerBlock, pieces * 4);
  }
}

void FiveAxisCutter::cut(const Block& block, const std::function<void(const Block&, const JointMotion&)>& piece) {
  const MachineModel& m = machine_;
  const auto where = [&block] { return "line " + std::to_string(block.line) + ": "; };
  for (int k = 0; k < 3; ++k)
    if ((programmed_[k] != 0.0 || block.rotaryEnd[k] != 0.0) && m.rotaryIndex(char('A' + k)) < 0)
      throw InputError(where() + "the program turns " + std::string(1, char('A' + k)) + " but machine \"" + m.name +
                       "\" has no such axis" + (m.hasRotaryAxes() ? " (it has " + m.kinematicsName() + " axes)" : "") +
                       ": choose the machine the program was posted for");
  if (block.orientationVectors && !m.hasRotaryAxes())
    throw InputError(where() + "the program gives tool orientations (A3 B3 C3) but machine \"" + m.name +
                     "\" has no rotary axes: choose a 5-axis machine");

  // Pieces: one per degree of rotary motion (of the orientation for vectors), per 5° of an arc.
  const RotaryAngles startAngles = previous_;
  double turn = 0.0;
  if (block.orientationVectors && !block.orientationByAxes) {
    if (orientation_.squaredNorm() == 0.0) orientation_ = toolAxisAt(m, previous_);  // the first vector
    turn = degreesBetween(orientation_, block.orientationEnd);
  } else {
    fromAngles_ = toAngles_ = previous_;
    if (block.orientationVectors) {  // ORIMKS/ORIAXES: the end's angles, reached axis by axis
      try {
        toAngles_ = inverseKinematics(m, {block.end, block.orientationEnd}, previous_).position.angles;
      } catch (const InputError& error) {
        throw InputError(where() + error.what());
      }
    } else {
      for (size_t i = 0; i < m.rotaryAxes.size(); ++i) {
        const RotaryAxis& axis = m.rotaryAxes[i];
        const int k = axis.name - 'A';
        if (block.rotaryEnd[k] != programmed_[k]) toAngles_[i] = block.rotaryEnd[k];
        // An angle word the axis cannot reach: a real controller stops at its software limit (an alarm).
        if (!axis.continuous && !(toAngles_[i] >= axis.minPosition - 1e-9 && toAngles_[i] <= axis.maxPosition + 1e-9))
          throw InputError(where() + std::string(1, axis.name) + hsm::number(toAngles_[i]) + " is outside the travel of " +
                           std::string(1, axis.name) + " on machine \"" + m.name + "\" [" +
                           hsm::number(axis.minPosition) + ", " + hsm::number(axis.maxPosition) +
                           "] deg: correct the program, or choose the machine it was posted for");
      }
    }
    turn = std::max(std::abs(toAngles_[0] - fromAngles_[0]), std::abs(toAngles_[1] - fromAngles_[1]));
    if (m.rotaryPlanner == RotaryPlanner::LinuxCnc && !block.orientationVectors && !block.isArc())
      return programPiece(block, piece);
  }
  int pieces = static_cast<int>(std::ceil(turn / kDegreesPerPiece));
  if (block.isArc()) pieces = std::max(pieces, static_cast<int>(std::ceil(std::abs(block.sweep) * 180.0 / M_PI / kArcDegreesPerPiece)));
  pieces = std::clamp(pieces, 1, kMaxPiecesPerBlock);

  std::vector<JointVector>& q = q_;
  try {
    sample(block, startAngles, pieces, q);
  } catch (const InputError& error) {
    throw InputError(where() + error.what());
  }
  if (pieces == 1 && !block.isArc()) return onePiece(block, q[0], q[1], piece);

  // The feed's path: the tip (tip programmed) or X Y Z (machine axes); the rotary angle when neither moves.
  const bool tip = block.toolTip || m.toolTipProgrammed;
  std::vector<Eigen::Vector3d>& points = points_;
  points.resize(pieces + 1);
  for (int i = 0; i <= pieces; ++i) {
    if (tip) {
      const double lambda = double(i) / pieces;
      points[i] = block.isArc() ? block.pointAt(lambda * block.length()) : block.start + lambda * (block.end - block.start);
    } else {
      MachinePosition position{q[i].head<3>(), {q[i][3], q[i][4]}};
      points[i] = forwardKinematics(m, position).tip;
    }
  }
  std::vector<double>& ds = ds_;
  std::vector<double>& tipLength = tipLength_;
  ds.resize(pieces);
  tipLength.resize(pieces);
  double linear = 0.0;
  for (int i = 0; i < pieces; ++i) {
    tipLength[i] = (points[i + 1] - points[i]).norm();
    ds[i] = tip ? tipLength[i] : (q[i + 1].head<3>() - q[i].head<3>()).norm();
    linear += ds[i];
  }
  const bool rotaryOnly = linear < 1e-6;
  if (rotaryOnly)
    for (int i = 0; i < pieces; ++i) ds[i] = (q[i + 1].tail<2>() - q[i].tail<2>()).norm();
  double total = 0.0;
  for (double d : ds) total += d;

  std::vector<JointVector>& rate = rate_;
  std::vector<JointVector>& bend = bend_;
  rate.resize(pieces);
  bend.assign(pieces + 1, JointVector::Zero());
  for (int i = 0; i < pieces; ++i) rate[i] = ds[i] > 0.0 ? JointVector((q[i + 1] - q[i]) / ds[i]) : JointVector::Zero();
  for (int i = 1; i < pieces; ++i) {
    const double span = 0.5 * (ds[i - 1] + ds[i]);
    if (span > 0.0) bend[i] = (rate[i] - rate[i - 1]) / span;
  }
  Block b = block;
  if (b.isArc()) b.motion = Motion::Linear;  // the pieces are chords of the arc
  // G93: the whole block lasts 1/F, so its path speed is its length × F.
  if (block.inverseTime) b.feed = total * block.feed;
  b.rateLength = total;  // the block-processing limit counts the program's block, not its pieces
  JointMotion joint;
  joint.active = true;
  for (int i = 0; i < pieces; ++i) {
    if (!(ds[i] > 0.0)) continue;
    b.start = points[i];
    b.end = points[i + 1];
    joint.pathLength = ds[i];
    joint.tipLength = tipLength[i];
    joint.rotaryOnly = rotaryOnly;
    joint.rate = rate[i];
    joint.curvature = bend[i].cwiseAbs().cwiseMax(bend[i + 1].cwiseAbs());
    joint.start = q[i];
    joint.end = q[i + 1];
    piece(b, joint);
  }
  ended(block, q.back());
}

// A line whose axes turn less than a degree, the usual block of a 5-axis finishing program: what cut() does
// for one piece, without its arrays of pieces (their bookkeeping was most of a block's cost). Its rates are
// constant along it: no curvature.
void FiveAxisCutter::onePiece(const Block& block, const JointVector& q0, const JointVector& q1,
                              const std::function<void(const Block&, const JointMotion&)>& piece) {
  const MachineModel& m = machine_;
  const bool tip = block.toolTip || m.toolTipProgrammed;
  Block b = block;
  if (tip) {
    b.end = block.start + (block.end - block.start);  // as cut() interpolates its pieces' ends
  } else {
    b.start = forwardKinematics(m, {q0.head<3>(), {q0[3], q0[4]}}).tip;
    b.end = forwardKinematics(m, {q1.head<3>(), {q1[3], q1[4]}}).tip;
  }
  JointMotion joint;
  joint.active = true;
  joint.tipLength = (b.end - b.start).norm();
  const double linear = tip ? joint.tipLength : (q1.head<3>() - q0.head<3>()).norm();
  joint.rotaryOnly = linear < 1e-6;
  joint.pathLength = joint.rotaryOnly ? (q1.tail<2>() - q0.tail<2>()).norm() : linear;
  if (block.inverseTime) b.feed = joint.pathLength * block.feed;
  b.rateLength = joint.pathLength;
  if (joint.pathLength > 0.0) {
    joint.rate = (q1 - q0) / joint.pathLength;
    joint.start = q0;
    joint.end = q1;
    piece(b, joint);
  }
  ended(block, q1);
}

// Where the program and the machine are once `block` is cut, its last joints `joints`.
void FiveAxisCutter::ended(const Block& block, const JointVector& joints) {
  previous_ = {joints[3], joints[4]};
  programmed_ = block.rotaryEnd;
  // The tool axis of angles is asked for only when a vector follows: zero says so.
  orientation_ = block.orientationVectors ? block.orientationEnd : Eigen::Vector3d::Zero();
  remember(block, block.end, joints);
}

// The machine's axes where the block starts: where the block before it ended when it starts there, at the same
// angles and in the same frame (one kinematics evaluation a block instead of two).
JointVector FiveAxisCutter::startJoints(const Block& block, const RotaryAngles& angles) {
  const bool tip = block.toolTip || machine_.toolTipProgrammed;
  if (endKnown_ && endTip_ == tip && endPoint_ == block.start && endJoints_[3] == angles[0] &&
      endJoints_[4] == angles[1] && !(block.orientationVectors && !block.orientationByAxes))
    return endJoints_;
  return jointsAt(block, 0.0);
}

void FiveAxisCutter::remember(const Block& block, const Eigen::Vector3d& end, const JointVector& joints) {
  endKnown_ = true;
  endTip_ = block.toolTip || machine_.toolTipProgrammed;
  endPoint_ = end;
  endJoints_ = joints;
}

}  // namespace hsm::kinematics
