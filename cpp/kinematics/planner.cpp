#include "kinematics/planner.hpp"

#include "common/error.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::kinematics::detail {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTangentCosine = 1.0 - 1e-12;  // junctions straighter than this are not corners
// LinuxCNC 2.9 splits the acceleration on arcs and blends: 0.866·a normal, 0.5·a tangential (0.866² + 0.5² = 1).
constexpr double kLinuxCncNormalShare = 0.866;
constexpr double kLinuxCncTangentShare = 0.5;
constexpr double kLinuxCncKinkShare = 0.2165;  // a kink φ in one cycle T is taken while v·φ/T ≤ 0.2165·a

// A corner of deflection φ in the half-angle terms its blends need, from cos φ alone (no acos, cos, tan:
// they were a tenth of the simulation's time).
struct Corner {
  double cosHalf, sinHalf, tanHalf, sinPhi;
  explicit Corner(double cosine)
      : cosHalf(std::sqrt(0.5 * (1.0 + cosine))), sinHalf(std::sqrt(0.5 * (1.0 - cosine))),
        tanHalf(sinHalf / cosHalf), sinPhi(2.0 * sinHalf * cosHalf) {}
};

// Radius of the arc that rounds a corner within `tolerance` of the corner point, using at most half of each
// block (the rule of 840D rounding, LinuxCNC blends and grbl's junction deviation).
double blendRadius(const Corner& corner, double tolerance, double shorter) {
  const double c = corner.cosHalf;
  const double byTolerance = std::isfinite(tolerance) ? tolerance * c / std::max(1e-300, 1.0 - c) : kInfinity;
  const double byLength = 0.5 * shorter / corner.tanHalf;
  return std::min(byTolerance, byLength);
}
}  // namespace

Planner::Planner(const MachineModel& machine, Commit commit) : machine_(machine), commit_(std::move(commit)) {
  if (machine.lookAheadBlocks < 2)
    throw InputError("look_ahead_blocks = " + std::to_string(machine.lookAheadBlocks) + ": the planner needs 2 or more");
  ring_.resize(static_cast<size_t>(machine.lookAheadBlocks));
}

Segment Planner::prepare(const Block& block, long source) const {
  const MachineModel& m = machine_;
  Segment s;
  s.block = block;
  s.source = source;
  s.length = block.length();
  s.startTangent = block.tangent(false);
  s.endTangent = block.tangent(true);
  const bool linuxcnc = m.controller == ControllerKind::LinuxCNC;
  const bool rapid = block.motion == Motion::Rapid;
  s.dynamics.jerkLimited = m.controller == ControllerKind::Siemens840D &&
                           (block.jerkLimited >= 0 ? block.jerkLimited == 1 : m.jerkLimitedByDefault);

  double velocity, rapidVelocity, curvatureLimit = kInfinity;
  if (block.isArc()) {
    // The tangent turns in the plane: the weakest in-plane axis bounds the whole arc.
    const Eigen::Vector3d inPlane = Eigen::Vector3d::Ones() - block.normal.cwiseAbs();
    const double along = std::abs(block.normal.dot(block.end - block.start)) / std::max(s.length, 1e-12);
    auto weakest = [&](const Eigen::Vector3d& limits) {
      double w = kInfinity;
      for (int i = 0; i < 3; ++i)
        if (inPlane[i] > 0.5) w = std::min(w, limits[i]);
      return along > 1e-12 ? std::min(w, projectedLimit(limits, block.normal.cwiseAbs() * along)) : w;
    };
    s.dynamics.acceleration = weakest(m.maxAcceleration);
    s.dynamics.jerk = weakest(m.maxJerk);
    velocity = weakest(m.maxVelocity);
    rapidVelocity = weakest(m.rapidVelocity);
    Dynamics normal = s.dynamics;
    if (linuxcnc) {
      normal.acceleration *= kLinuxCncNormalShare;
      s.dynamics.acceleration *= kLinuxCncTangentShare;
    }
    curvatureLimit = curvatureSpeed(block.radius, normal);
  } else {
    // Lines take the full axis acceleration along them: LinuxCNC 2.9 joins them by tangent blend arcs,
    // which have their own share (its parabolic blends, which halve it, are the fallback we do not model).
    const Eigen::Vector3d u = s.startTangent;
    s.dynamics.acceleration = projectedLimit(m.maxAcceleration, u);
    s.dynamics.jerk = projectedLimit(m.maxJerk, u);
    velocity = projectedLimit(m.maxVelocity, u);
    rapidVelocity = projectedLimit(m.rapidVelocity, u);
  }
  s.programmed = rapid ? rapidVelocity : block.feed;
  s.cruise = std::min({s.programmed, velocity, curvatureLimit});
  // Block-processing limit: a block lasts at least one interpolation cycle (an 840D compressed group: the
  // group does).
  const double rateLength = block.rateLength > 0.0 ? block.rateLength : s.length;
  if (m.interpolationCycle > 0.0) s.cruise = std::min(s.cruise, rateLength / m.interpolationCycle);
  return s;
}

Planner::Junction Planner::junction(const Segment& before, const Segment& after) const {
  const MachineModel& m = machine_;
  const double limit = std::min(before.cruise, after.cruise);
  const bool grbl = m.controller == ControllerKind::Grbl;
  if (before.block.pathMode == PathMode::ExactStop && !grbl) return {};
  const bool rapidBefore = before.block.motion == Motion::Rapid, rapidAfter = after.block.motion == Motion::Rapid;
  if (m.controller == ControllerKind::Siemens840D && rapidBefore != rapidAfter) return {};  // G0 ends in exact stop

  const double cosine = std::clamp(before.endTangent.dot(after.startTangent), -1.0, 1.0);
  Junction j;
  if (cosine >= kTangentCosine) {
    j.speed = limit;
    return j;
  }
  if (cosine <= -1.0 + 1e-9) return j;  // the path turns back
  const Corner corner(cosine);
  const double shorter = std::min(before.length, after.length);
  Dynamics d = before.dynamics;
  d.acceleration = std::min(before.dynamics.acceleration, after.dynamics.acceleration);
  d.jerk = std::min(before.dynamics.jerk, after.dynamics.jerk);
  d.jerkLimited = before.dynamics.jerkLimited || after.dynamics.jerkLimited;

  double v = 0.0;
  switch (m.controller) {
    case ControllerKind::Siemens840D: {
      const double jump = projectedLimit(m.velocityJump, after.startTangent - before.endTangent);
      v = jump;
      if (before.block.pathMode == PathMode::Rounding)
        v = std::max(v, curvatureSpeed(blendRadius(corner, before.block.tolerance, shorter), d));
      // A chain of short blocks is a curve: its radius through the three points bounds the speed, at the
      // junction and along both blocks (the look-ahead sees the curve, not the chords).
      const double chord = (after.block.end - before.block.start).norm();
      j.adjacentCap = curvatureSpeed(chord / (2.0 * corner.sinPhi), d);
      v = std::min(v, j.adjacentCap);
      break;
    }
    case ControllerKind::LinuxCNC: {
      const double tolerance = before.block.pathMode == PathMode::Rounding ? before.block.tolerance : kInfinity;
      const double full = std::min(projectedLimit(m.maxAcceleration, before.endTangent),
                                   projectedLimit(m.maxAcceleration, after.startTangent));
      // The blend arc is a curve in the plane of the two blocks: its normal acceleration may point anywhere
      // across the path, so it counts on the axes' limits within that plane, whatever the blocks' direction.
      const Eigen::Vector3d binormal = before.endTangent.cross(after.startTangent);
      const double across = binormal.norm() > 1e-12 ? inPlaneLimit(m.maxAcceleration, binormal.normalized()) : full;
      const double radius = blendRadius(corner, tolerance, shorter);
      const double blend = std::sqrt(kLinuxCncNormalShare * across * radius);
      j.blend = radius * corner.tanHalf;  // the tangent length the arc takes from each block
      const double kink = kLinuxCncKinkShare * full * m.interpolationCycle / std::acos(cosine);
      v = std::max(blend, kink);
      break;
    }
    case ControllerKind::Grbl: {
      const double full = std::min(projectedLimit(m.maxAcceleration, before.endTangent),
                                   projectedLimit(m.maxAcceleration, after.startTangent));
      v = std::sqrt(full * blendRadius(corner, m.cornerTolerance, kInfinity));
      break;
    }
  }
  j.speed = std::min(v, limit);
  return j;
}

void Planner::add(const Block& block, long source) {
  Segment segment = prepare(block, source);
  if (!(segment.length > 0.0) || !(segment.cruise > 0.0)) return;  // nothing to move
  // A block waits here until its successor is known: the junction between them may lower both cruises.
  if (havePending_) {
    const Junction j = junction(pending_, segment);
    // A block whose blend arcs take all of it (half at each end, both at most half of it) has no straight
    // part left: it runs at its blends' speed. Otherwise it cruises between them, however short the blends.
    if (j.blend > 0.0 && pending_.blendStart + j.blend >= pending_.length * (1.0 - 1e-9))
      pending_.cruise = std::min(pending_.cruise, std::max(pending_.blendStartSpeed, j.speed));
    segment.blendStart = j.blend;
    segment.blendStartSpeed = j.speed;
    pending_.cruise = std::min(pending_.cruise, j.adjacentCap);
    segment.cruise = std::min(segment.cruise, j.adjacentCap);
    pending_.junction = std::min(pending_.junction, pending_.cruise);
    segment.junction = std::min({j.speed, segment.cruise, pending_.cruise});
    if (count_ == ring_.size()) commitOldest();
    push(std::move(pending_));
  }
  pending_ = std::move(segment);
  havePending_ = true;
}

Dynamics weakest(const Dynamics& a, const Dynamics& b) {
  return {std::min(a.acceleration, b.acceleration), std::min(a.jerk, b.jerk), a.jerkLimited || b.jerkLimited};
}

void Planner::push(Segment segment) {
  segment.position = nextPosition_;
  nextPosition_ += segment.length;
  if (count_ == 0 && segment.position == 0.0) segment.entry = 0.0;  // the program starts from rest
  const size_t index = count_;
  at(count_++) = std::move(segment);
  // Backward pass. A junction binds when its own limit is below what the machine could reach backwards
  // from the next binding junction downstream (or from the end of the newest block, where it must be
  // able to stop). A new block only moves the end further, so junctions stop binding from the back: each
  // is dropped once, and a pass costs O(1) on average instead of a walk over the whole look-ahead.
  const Segment& newest = at(index);
  const double end = nextPosition_;
  const bool newestBinds =
      index > 0 && withinReach(newest.junction, 0.0, end - newest.position, newest.dynamics);
  while (!binding_.empty()) {
    const Segment& b = at(binding_.back() - committed_);
    const double downstreamSpeed = newestBinds ? newest.junction : 0.0;
    const double downstreamPosition = newestBinds ? newest.position : end;
    if (withinReach(b.junction, downstreamSpeed, downstreamPosition - b.position, weakest(b.dynamics, newest.dynamics)))
      break;
    binding_.pop_back();
  }
  if (newestBinds) binding_.push_back(committed_ + index);
}

// The planned entry of the block at ring index i (> 0): its junction's own limit if it binds, else what
// the machine can reach backwards from the next binding junction (or the stop at the end).
double Planner::plannedEntry(size_t i) {
  const long number = committed_ + static_cast<long>(i);
  while (!binding_.empty() && binding_.front() < number) binding_.pop_front();
  const Segment& s = at(i);
  if (!binding_.empty() && binding_.front() == number) return s.junction;
  const Segment& downstream = binding_.empty() ? at(count_ - 1) : at(binding_.front() - committed_);
  const double speed = binding_.empty() ? 0.0 : downstream.junction;
  const double position = binding_.empty() ? nextPosition_ : downstream.position;
  return cappedReach(s.junction, speed, position - s.position, weakest(s.dynamics, downstream.dynamics));
}

void Planner::commitOldest() {
  Segment& s = at(0);
  const bool hasNext = count_ > 1;
  const double end = s.position + s.length;
  forwardDynamics_ = weakest(forwardDynamics_, s.dynamics);
  const double planned = hasNext ? plannedEntry(1) : 0.0;  // the machine stops at the end of the program
  const double cap = hasNext ? at(1).junction : 0.0;
  const double exit = cappedReach(planned, forwardSpeed_, end - forwardPosition_, forwardDynamics_);
  const bool pinned = !hasNext || exit >= cap * (1.0 - 1e-12);
  if (pinned) {
    forwardSpeed_ = exit;
    forwardPosition_ = end;
    forwardDynamics_ = hasNext ? at(1).dynamics : s.dynamics;
  }
  if (hasNext) at(1).entry = exit;
  commit_(s, s.entry, exit, pinned);
  head_ = (head_ + 1) % ring_.size();
  --count_;
  ++committed_;
}

void Planner::finish() {
  if (havePending_) {
    // LinuxCNC keeps a parabolic end on the last line of a blending mode (no next block to blend it with
    // by an arc), and a parabolic blend halves the line's acceleration (tp.c, tpGetScaledAccel).
    const bool parabolicEnd = machine_.controller == ControllerKind::LinuxCNC && !pending_.block.isArc() &&
                              pending_.block.pathMode != PathMode::ExactStop;
    if (parabolicEnd) pending_.dynamics.acceleration *= kLinuxCncTangentShare;
    if (count_ == ring_.size()) commitOldest();
    push(std::move(pending_));
    havePending_ = false;
  }
  while (count_ > 0) commitOldest();
}

}  // namespace hsm::kinematics::detail
