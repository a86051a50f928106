#include "kinematics/planner.hpp"

#include "common/error.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <vector>

namespace hsm::kinematics::detail {

namespace {
// The joint motions of 5-axis blocks come and go in program order, a few hundred alive at a time: their
// nodes (the motion and its shared count, `Bytes` each) are kept on a free list of this thread for the next
// block, so the planner asks the heap for no memory per block; at most 4096 are kept.
template <size_t Bytes>
class NodeList {
public:
  ~NodeList() {
    for (void* node : free_) ::operator delete(node);
  }
  void* take() {
    if (free_.empty()) return ::operator new(Bytes);
    void* node = free_.back();
    free_.pop_back();
    return node;
  }
  void give(void* node) {
    if (free_.size() >= kKept) return ::operator delete(node);
    free_.push_back(node);
  }
  static NodeList& ofThisThread() {
    thread_local NodeList list;
    return list;
  }

private:
  static constexpr size_t kKept = 4096;
  std::vector<void*> free_;
};

template <class T>
struct RecycledNodes {
  using value_type = T;
  RecycledNodes() = default;
  template <class U>
  RecycledNodes(const RecycledNodes<U>&) {}
  T* allocate(size_t n) {
    return static_cast<T*>(n == 1 ? NodeList<sizeof(T)>::ofThisThread().take() : ::operator new(n * sizeof(T)));
  }
  void deallocate(T* p, size_t n) { n == 1 ? NodeList<sizeof(T)>::ofThisThread().give(p) : ::operator delete(p); }
  template <class U>
  bool operator==(const RecycledNodes<U>&) const { return true; }
  template <class U>
  bool operator!=(const RecycledNodes<U>&) const { return false; }
};

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTangentCosine = 1.0 - 1e-12;  // junctions straighter than this are not corners
// LinuxCNC 2.9 splits the acceleration on arcs and blends: 0.866·a normal, 0.5·a tangential (0.866² + 0.5² = 1).
constexpr double kLinuxCncNormalShare = 0.866;
constexpr double kLinuxCncTangentShare = 0.5;
constexpr double kLinuxCncKinkRatio = 0.1;  // ARC_BLEND_KINK_RATIO: a kink's share of the axis acceleration
constexpr double kLinuxCncGapCycles = 4.0;  // ARC_BLEND_GAP_CYCLES: a blend arc takes a shorter rest of the block before
constexpr double kLinuxCncSegmentCycles = 1.02;  // TP_MIN_SEGMENT_CYCLES: blend pieces last this many cycles
const double kLinuxCncReversal = std::cos(178.0 * M_PI / 180.0);  // reversals within 2° stop

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
  jointVelocity_ << machine.maxVelocity, kInfinity, kInfinity;
  jointRapid_ << machine.rapidVelocity, kInfinity, kInfinity;
  jointAcceleration_ << machine.maxAcceleration, kInfinity, kInfinity;
  jointJerk_ << machine.maxJerk, kInfinity, kInfinity;
  for (size_t i = 0; i < machine.rotaryAxes.size(); ++i) {
    const RotaryAxis& a = machine.rotaryAxes[i];
    jointVelocity_[3 + i] = a.maxVelocity;
    jointRapid_[3 + i] = a.rapidVelocity;
    jointAcceleration_[3 + i] = a.maxAcceleration;
    jointJerk_[3 + i] = a.maxJerk;
  }
  inverseVelocity_ = jointVelocity_.cwiseInverse();  // an infinite limit costs nothing: 0
  inverseRapid_ = jointRapid_.cwiseInverse();
  inverseAcceleration_ = jointAcceleration_.cwiseInverse();
  inverseJerk_ = jointJerk_.cwiseInverse();
}

namespace {
// The most an axis allows along the path: min over axes of limit / |rate|, from the limits' inverses (one
// division, not five); the index of that axis in `which`.
double projected(const JointVector& inverseLimits, const JointVector& rate, int& which) {
  double most = 0.0;
  which = -1;
  for (int i = 0; i < 5; ++i) {
    const double r = std::abs(rate[i]);
    if (r > 1e-12 && r * inverseLimits[i] > most) {
      most = r * inverseLimits[i];
      which = i;
    }
  }
  return most > 0.0 ? 1.0 / most : kInfinity;
}

SpeedLimit axisLimit(const MachineModel& m, int joint) {
  if (joint < 3) return static_cast<SpeedLimit>(static_cast<int>(SpeedLimit::X) + joint);
  return static_cast<SpeedLimit>(static_cast<int>(SpeedLimit::A) + (m.rotaryAxes[joint - 3].name - 'A'));
}
}  // namespace

SpeedLimit Planner::slowestAxis(const JointVector& inverseLimits, const Eigen::Vector3d& tangent) const {
  int which = -1;
  JointVector direction;
  direction << tangent, 0.0, 0.0;
  projected(inverseLimits, direction, which);
  return which >= 0 ? axisLimit(machine_, which) : SpeedLimit::Feed;
}

void Planner::jointLimits(Segment& s, const JointMotion& joint, double& velocity, double& rapidVelocity,
                          double& curvatureLimit) const {
  // The four projected limits in one pass over the axes, as projected() takes each (it runs for every piece).
  double acceleration = 0.0, jerk = 0.0, speed = 0.0, rapid = 0.0;
  int accelerationAxis = -1, speedAxis = -1;
  for (int i = 0; i < 5; ++i) {
    const double r = std::abs(joint.rate[i]);
    if (!(r > 1e-12)) continue;
    if (r * inverseAcceleration_[i] > acceleration) {
      acceleration = r * inverseAcceleration_[i];
      accelerationAxis = i;
    }
    if (r * inverseVelocity_[i] > speed) {
      speed = r * inverseVelocity_[i];
      speedAxis = i;
    }
    jerk = std::max(jerk, r * inverseJerk_[i]);
    rapid = std::max(rapid, r * inverseRapid_[i]);
  }
  const auto inverse = [](double most) { return most > 0.0 ? 1.0 / most : kInfinity; };
  s.dynamics.acceleration = inverse(acceleration);
  s.accelerationLimit = accelerationAxis >= 0 ? axisLimit(machine_, accelerationAxis) : SpeedLimit::Feed;
  s.dynamics.jerk = inverse(jerk);
  velocity = inverse(speed);
  rapidVelocity = inverse(rapid);
  s.limit = speedAxis >= 0 ? axisLimit(machine_, speedAxis) : SpeedLimit::Feed;
  // Where an axis's rate changes along the path, at speed v it needs curvature·v² of acceleration.
  for (int i = 0; i < 5; ++i)
    if (joint.curvature[i] > 1e-12) {
      const double v = std::sqrt(jointAcceleration_[i] / joint.curvature[i]);
      if (v < curvatureLimit) {
        curvatureLimit = v;
        if (v < velocity) s.limit = axisLimit(machine_, i);
      }
    }
}

Segment Planner::prepare(const Block& block, long source, const JointMotion* joint) const {
  const MachineModel& m = machine_;
  Segment s;
  s.block = block;
  s.source = source;
  s.length = joint ? joint->pathLength : block.length();
  // The tip's tangents, except where a 4- or 5-axis block's corners are its machine direction's (below).
  const auto tipTangents = [&s, &block] {
    s.startTangent = block.tangent(false);
    s.endTangent = block.tangent(true);
  };
  const bool linuxcnc = m.controller == ControllerKind::LinuxCNC;
  const bool rapid = block.motion == Motion::Rapid;
  s.dynamics.jerkLimited = m.controller == ControllerKind::Siemens840D &&
                           (block.jerkLimited >= 0 ? block.jerkLimited == 1 : m.jerkLimitedByDefault);

  double velocity, rapidVelocity, curvatureLimit = kInfinity;
  if (joint) {
    s.joint = std::allocate_shared<const JointMotion>(RecycledNodes<JointMotion>(), *joint);
    if (m.rotaryPlanner == RotaryPlanner::LinuxCnc) {
      // LinuxCNC's directions are the program's X Y Z; a turn of the rotary axes alone gets +X, as posemath
      // gives a line of no length (pmCartLineInit), which its parabolic blends read.
      const Eigen::Vector3d along = joint->rotaryOnly ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(joint->rate.head<3>());
      s.startTangent = s.endTangent = along.norm() > 1e-12 ? along.normalized() : Eigen::Vector3d::UnitX();
    } else {
      // Corners are the machine's: X Y Z's direction (the tip's in the workpiece frame is turned by the table).
      const Eigen::Vector3d machineDirection = joint->end.head<3>() - joint->start.head<3>();
      if (machineDirection.norm() > 1e-12)
        s.startTangent = s.endTangent = machineDirection.normalized();
      else
        tipTangents();
    }
    jointLimits(s, *joint, velocity, rapidVelocity, curvatureLimit);
  } else if (tipTangents(); block.isArc()) {
    // The tangent turns in the plane: it points, somewhere on the arc, as far along each axis as the plane lets
    // it (sqrt(1 - n_i²) of the speed: all of it for the two axes of G17/G18/G19, part of it in a turned
    // frame's plane), so the weakest axis for its share bounds the whole arc.
    const double along = std::abs(block.normal.dot(block.end - block.start)) / std::max(s.length, 1e-12);
    auto weakest = [&](const Eigen::Vector3d& limits) {
      const double w = inPlaneLimit(limits, block.normal);
      return along > 1e-12 ? std::min(w, projectedLimit(limits, block.normal.cwiseAbs() * along)) : w;
    };
    s.dynamics.acceleration = weakest(m.maxAcceleration);
    s.dynamics.jerk = weakest(m.maxJerk);
    velocity = weakest(m.maxVelocity);
    rapidVelocity = weakest(m.rapidVelocity);
    Dynamics normal = s.dynamics;
    if (linuxcnc) {
      // LinuxCNC keeps 0.866·a across the arc, and along it what the arc's top speed leaves
      // (pmCircleActualMaxVel): a·sqrt(1 − (v_max²/R / a)²) with v_max the machine's speed on the arc, so half
      // of a on arcs tight enough that the top speed is the curvature's.
      normal.acceleration *= kLinuxCncNormalShare;
      const double top = std::min(velocity, std::sqrt(normal.acceleration * block.radius));
      const double centripetal = std::min(top * top / block.radius, normal.acceleration) / s.dynamics.acceleration;
      s.dynamics.acceleration *= std::sqrt(std::max(0.0, 1.0 - centripetal * centripetal));
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
  if (s.cruise >= s.programmed) {
    s.limit = SpeedLimit::Feed;
  } else if (s.cruise == curvatureLimit && !joint) {
    s.limit = SpeedLimit::Curvature;
  } else if (!joint) {  // the slowest axis along the block's start tangent
    s.limit = slowestAxis(rapid ? inverseRapid_ : inverseVelocity_, s.startTangent);
  }
  // Block-processing limit: a block lasts at least one interpolation cycle (an 840D compressed group: the
  // group does).
  const double rateLength = block.rateLength > 0.0 ? block.rateLength : s.length;
  if (m.interpolationCycle > 0.0 && rateLength / m.interpolationCycle < s.cruise) {
    s.cruise = rateLength / m.interpolationCycle;
    s.limit = SpeedLimit::BlockRate;
  }
  return s;
}

Planner::Junction Planner::junction(const Segment& before, const Segment& after) const {
  // LinuxCNC never blends a rapid with a feed move: the segment before stops, at its full acceleration (tp.c
  // handleModeChange).
  if (machine_.controller == ControllerKind::LinuxCNC &&
      (before.block.motion == Motion::Rapid) != (after.block.motion == Motion::Rapid))
    return {};
  if (!before.joint && !after.joint) return tipJunction(before, after);
  if (machine_.rotaryPlanner == RotaryPlanner::LinuxCnc && before.source != after.source) {
    // LinuxCNC makes neither a tangent junction nor a blend arc where a block turns a rotary axis, and its
    // look-ahead stops there (tp.c: tcRotaryMotionCheck in tpSetupTangent and tpCheckBlendArcType).
    Junction j;
    j.rotaryStop = true;
    return j;
  }
  return jointJunction(before, after);
}

// Between pieces of one block the axes' rates change smoothly (their curvature bounds the cruise); between
// blocks the tool tip's corner is the 3-axis rule, and each rotary axis may change its velocity by what its
// acceleration gives in one interpolation cycle (all axes when the tip does not move).
Planner::Junction Planner::jointJunction(const Segment& before, const Segment& after) const {
  auto rotaryOnly = [](const Segment& s) { return s.joint && s.joint->rotaryOnly; };
  const double limit = std::min(before.cruise, after.cruise);
  Junction j;
  if (before.source == after.source) {
    j.speed = limit;
    return j;
  }
  // The feed changes its meaning (mm/min of the path, deg/min of the rotary axes): the controller stops.
  if (before.block.pathMode == PathMode::ExactStop || rotaryOnly(before) != rotaryOnly(after)) return j;
  auto tipLength = [](const Segment& s) { return s.joint ? s.joint->tipLength : s.length; };
  auto rate = [](const Segment& s) {
    if (s.joint) return s.joint->rate;
    JointVector r = JointVector::Zero();
    r.head<3>() = s.startTangent;
    return r;
  };
  const bool tipMoves = tipLength(before) > 1e-9 && tipLength(after) > 1e-9;
  if (tipMoves) {
    j = tipJunction(before, after);
    j.trim = j.arcLength = 0.0;  // no LinuxCNC blend arc between 5-axis blocks (not modelled)
  } else {
    j.speed = limit;
  }
  const double cycle = machine_.interpolationCycle > 0.0 ? machine_.interpolationCycle : 1e-3;
  const JointVector change = rate(after) - rate(before);
  for (int i = tipMoves ? 3 : 0; i < 5; ++i)
    if (std::abs(change[i]) > 1e-12) j.speed = std::min(j.speed, jointAcceleration_[i] * cycle / std::abs(change[i]));
  return j;
}

Planner::Junction Planner::tipJunction(const Segment& before, const Segment& after) const {
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
  // The path turns back (LinuxCNC stops at reversals within 2°, even in G64).
  if (cosine <= (m.controller == ControllerKind::LinuxCNC ? kLinuxCncReversal : -1.0 + 1e-9)) return j;
  const Corner corner(cosine);
  const double shorter = std::min(before.length, after.length);
  Dynamics d = before.dynamics;
  d.acceleration = std::min(before.dynamics.acceleration, after.dynamics.acceleration);
  d.jerk = std::min(before.dynamics.jerk, after.dynamics.jerk);
  d.jerkLimited = before.dynamics.jerkLimited || after.dynamics.jerkLimited;

  double v = 0.0;
  switch (m.controller) {
    case ControllerKind::Siemens840D: {
      // A chain of short blocks is a curve: its radius through the three points bounds the speed, at the
      // junction and along both blocks (the look-ahead sees the curve, not the chords).
      const double chord = (after.block.end - before.block.start).norm();
      j.adjacentCap = curvatureSpeed(chord / (2.0 * corner.sinPhi), d);
      v = projectedLimit(m.velocityJump, after.startTangent - before.endTangent);
      // Rounding lets the corner go faster than the jump allows, up to what its blend's radius allows; where
      // the jump already reaches the cap, the blend changes nothing.
      if (before.block.pathMode == PathMode::Rounding && v < std::min(limit, j.adjacentCap))
        v = std::max(v, curvatureSpeed(blendRadius(corner, before.block.tolerance, shorter), d));
      v = std::min(v, j.adjacentCap);
      break;
    }
    case ControllerKind::LinuxCNC:
      v = linuxCncCorner(before, after, corner, cosine, limit, j);
      break;
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

// LinuxCNC 2.9's corner (tp.c tpSetupTangent, blendmath.c blendComputeParameters, as the oracle measured it).
// A kink that takes less than a tenth of the axis limits in one cycle is passed as tangent (both blocks give
// up that share of their acceleration). Otherwise a tangent blend arc, within the tolerance (G64 P, or a
// quarter of the shorter block without P) and half of each block, planned for the requested speed and at
// least as large as an equivalent parabolic blend would run; or the kink's own speed where that is faster.
double Planner::linuxCncCorner(const Segment& before, const Segment& after, const Corner& corner, double cosine,
                               double limit, Junction& j) const {
  const MachineModel& m = machine_;
  const double k = linuxCncKink(before, after, limit);
  if (k < kLinuxCncKinkRatio) {
    j.kinkShare = k;
    return limit;
  }
  const double shorter = std::min(before.block.length(), after.block.length());
  const double tolerance = before.block.pathMode == PathMode::Rounding ? before.block.tolerance : 0.25 * shorter;
  // The arc is a curve in the plane of the two blocks: its normal acceleration may point anywhere across the
  // path, so it counts on the axes' limits within that plane, whatever the blocks' direction.
  const Eigen::Vector3d binormal = before.endTangent.cross(after.startTangent);
  const double full = std::min(before.dynamics.acceleration, after.dynamics.acceleration);
  const double across = binormal.norm() > 1e-12 ? inPlaneLimit(m.maxAcceleration, binormal.normalized()) : full;
  const double normal = kLinuxCncNormalShare * across;
  const double phi = std::atan2(corner.sinPhi, cosine);
  const double half = std::min(std::min(before.length, 0.5 * before.block.length()), 0.5 * after.length);
  const double geometric = blendRadius(corner, tolerance, 2.0 * half);
  const double plan = std::min(std::sqrt(normal * geometric), limit);
  const double kink = limit * kLinuxCncKinkRatio / k;
  // No arc where the kink is faster, nor between blocks too short to last a servo cycle at the programmed
  // feed: the oracle shows LinuxCNC passing chains of such chords (G64 P… Q0) at the kink's speed.
  if (kink >= plan) {
    j.parabolic = true;  // the blend stays parabolic: both blocks plan with half their acceleration
    return kink;
  }
  const double parabolic = 0.5 * across;  // the blend a parabolic one would make: as long as its time at plan
  const double sweep = std::min(std::sqrt(2.0 * parabolic * geometric * corner.tanHalf), plan) / parabolic * plan;
  const double radius = std::max(plan * plan / normal, std::min(sweep / phi, geometric));
  j.trim = radius * corner.tanHalf;
  j.arcLength = radius * phi;
  j.arcAcceleration = kLinuxCncTangentShare * across;
  return plan;
}

// The share k of the axis limits that turning from `before` to `after` within one cycle T at v takes:
// max_i (v/T + a)·|Δu_i| / a_i (tp.c tpSetupTangent).
double Planner::linuxCncKink(const Segment& before, const Segment& after, double v) const {
  const Eigen::Vector3d turn = (after.startTangent - before.endTangent).cwiseAbs();
  const double surge = v / machine_.interpolationCycle + std::min(before.dynamics.acceleration, after.dynamics.acceleration);
  double k = 0.0;
  for (int i = 0; i < 3; ++i) k = std::max(k, surge * turn[i] / machine_.maxAcceleration[i]);
  return k;
}

// LinuxCNC's exact stop at a corner (G61): it rates the corner as a kink and takes a tenth of the
// acceleration of both blocks for it (once per block), then stops there for one servo cycle.
void Planner::linuxCncExactStop(Segment& before, Segment& after) const {
  // Where a rotary axis turns no kink is rated, and the next block starts in the cycle this one stops in.
  if (machine_.rotaryPlanner == RotaryPlanner::LinuxCnc && (before.joint || after.joint)) return;
  const double cosine = before.endTangent.dot(after.startTangent);
  if (cosine >= kTangentCosine) return;
  if (linuxCncKink(before, after, std::min(before.cruise, after.cruise)) < kLinuxCncKinkRatio) return;
  for (Segment* s : {&before, &after})
    if (!s->kinkScaled) {
      s->dynamics.acceleration *= 1.0 - kLinuxCncKinkRatio;
      s->kinkScaled = true;
    }
  before.restAfter = machine_.interpolationCycle;
}

void Planner::add(const Block& block, long source, const JointMotion* joint) {
  Segment segment = prepare(block, source, joint);
  if (!(segment.length > 0.0) || !(segment.cruise > 0.0)) return;  // nothing to move
  // A block waits here until its successor is known: the junction between them may lower both cruises.
  if (havePending_) {
    if (machine_.controller == ControllerKind::LinuxCNC && pending_.block.pathMode == PathMode::ExactStop)
      linuxCncExactStop(pending_, segment);
    const Junction j = junction(pending_, segment);
    if (j.rotaryStop && pending_.block.pathMode != PathMode::ExactStop) {
      // The block before ends in a parabolic blend: half its acceleration (tc.c tcGetOverallMaxAccel).
      if (!pending_.parabolic) pending_.dynamics.acceleration *= kLinuxCncTangentShare;
      pending_.parabolic = true;
      segment.parabolicFromPrevious = true;
    }
    pending_.dynamics.acceleration *= 1.0 - j.kinkShare;
    segment.dynamics.acceleration *= 1.0 - j.kinkShare;
    if (j.parabolic)
      for (Segment* s : {&pending_, &segment})
        if (!s->parabolic) {
          s->dynamics.acceleration *= kLinuxCncTangentShare;
          s->parabolic = true;
        }
    pending_.cruise = std::min(pending_.cruise, j.adjacentCap);
    segment.cruise = std::min(segment.cruise, j.adjacentCap);
    pending_.junction = std::min(pending_.junction, pending_.cruise);
    segment.junction = std::min({j.speed, segment.cruise, pending_.cruise});
    if (j.trim > 0.0) {
      // The arc takes the corner: both blocks end or start where it is tangent to them. What is left of the
      // block before lasts a servo cycle at least, or, shorter than the arc runs in ARC_BLEND_GAP_CYCLES,
      // the arc takes it too (blendmath.c blendCheckConsume); the block after is timed once its end is known.
      pending_.length -= j.trim;
      segment.length -= j.trim;
      segment.trimmed = true;
      Segment arc = blendArc(pending_, segment, j);
      const double cycle = machine_.interpolationCycle;
      if (pending_.length < kLinuxCncGapCycles * cycle * j.speed && !pending_.parabolic) {
        arc.length += pending_.length;
        arc.block.start = pending_.block.end - (pending_.length + j.trim) * pending_.endTangent;
        arc.cruise = std::min(j.speed, arc.length / (kLinuxCncSegmentCycles * cycle));
        arc.junction = std::min(pending_.junction, arc.cruise);
      } else {
        lastsACycle(pending_);
        arc.junction = std::min(arc.junction, pending_.cruise);
        pushPending();
      }
      if (count_ == ring_.size()) commitOldest();
      push(std::move(arc));
    } else {
      if (pending_.trimmed) lastsACycle(pending_);
      segment.junction = std::min(segment.junction, pending_.cruise);
      pushPending();
    }
  }
  pending_ = std::move(segment);
  havePending_ = true;
}

// LinuxCNC's blend arc between `before` and `after`, as a segment of its own: it runs at its planned speed
// (and lasts a servo cycle at least), with its share of the acceleration along it.
Segment Planner::blendArc(const Segment& before, const Segment& after, const Junction& j) const {
  Segment arc = before;
  arc.length = j.arcLength;
  arc.block.motion = Motion::Linear;  // drawn and traced as its chord (within the tolerance of the arc)
  arc.block.start = before.block.end - j.trim * before.endTangent;
  arc.block.end = after.block.start + j.trim * after.startTangent;
  arc.startTangent = before.endTangent;
  arc.endTangent = after.startTangent;
  arc.blendArc = true;
  arc.programmedStart = before.block.start;
  arc.programmedEnd = before.block.end;
  arc.dynamics = {j.arcAcceleration, kInfinity, false};
  arc.cruise = std::min(j.speed, j.arcLength / (kLinuxCncSegmentCycles * machine_.interpolationCycle));
  arc.junction = std::min(j.speed, arc.cruise);
  arc.restAfter = 0.0;
  return arc;
}

// What blend arcs left of a block still lasts a servo cycle at least (tc.c tcClampVelocityByLength).
void Planner::lastsACycle(Segment& s) const {
  if (machine_.interpolationCycle > 0.0)
    s.cruise = std::min(s.cruise, s.length / (kLinuxCncSegmentCycles * machine_.interpolationCycle));
  s.junction = std::min(s.junction, s.cruise);
}

// The pending block's dynamics are final once its successor is known: its parabolic blend with the block
// before (the newest in the ring, not committed yet) can be timed, then it joins the ring.
void Planner::pushPending() {
  if (pending_.parabolicFromPrevious && count_ > 0) overlapParabolic(at(count_ - 1), pending_);
  if (count_ == ring_.size()) commitOldest();
  push(std::move(pending_));
}

// LinuxCNC's parabolic blend between two blocks planned from rest to rest (tp.c tpComputeBlendVelocity, as the
// oracle measured it): the next block starts once this one brakes below its blend speed, the speed either
// would reach in the longer of their times to full speed, within the time to run half of the shorter, and,
// under G64 P, the speed at which braking covers the tolerance across the corner. Both move together from
// then on, so the next block starts blend / a before this one ends.
void Planner::overlapParabolic(Segment& before, const Segment& after) const {
  const double a1 = before.dynamics.acceleration, a2 = after.dynamics.acceleration;
  const double v1 = std::min(std::sqrt(a1 * before.length), before.cruise);
  const double v2 = std::min(std::sqrt(a2 * after.length), after.cruise);
  if (!(v1 > 0.0 && v2 > 0.0)) return;
  const double time = std::min({before.length / v1, after.length / v2, std::max(v1 / a1, v2 / a2)});
  double blend = std::min(v1, time * a1);
  if (before.block.pathMode == PathMode::Rounding && before.block.tolerance > 0.0) {
    // cos of half the angle between the directions, taken as LinuxCNC's findIntersectionAngle takes it
    const double dot = std::clamp(before.endTangent.dot(after.startTangent), -1.0, 1.0);
    const double cosHalf = std::sqrt(0.5 * (1.0 - dot));
    if (cosHalf > std::sin(1e-3)) blend = std::min(blend, 2.0 * std::sqrt(a1 * before.block.tolerance / cosHalf));
  }
  before.restAfter = -blend / a1;
}

Dynamics weakest(const Dynamics& a, const Dynamics& b) {
  return {std::min(a.acceleration, b.acceleration), std::min(a.jerk, b.jerk), a.jerkLimited || b.jerkLimited};
}

void Planner::push(Segment&& segment) {
  segment.position = nextPosition_;
  nextPosition_ += segment.length;
  if (count_ == 0 && segment.position == 0.0) segment.entry = 0.0;  // the program starts from rest
  const size_t index = count_;
  at(count_++) = std::move(segment);
  // Backward pass. The junctions that may bind are kept in order, each one below what the machine could
  // reach backwards from the next: a new junction drops those it dominates (it is slower than the machine can
  // brake to from them), so a pass costs O(1) on average instead of a walk over the whole look-ahead. The stop
  // at the end of the newest block is applied apart (plannedEntry): a junction it dominates now, behind a
  // block too short to stop in, may bind once more blocks are known.
  const Segment& newest = at(index);
  if (index == 0) return;
  while (!binding_.empty()) {
    const Segment& b = at(binding_.back() - committed_);
    if (withinReach(b.junction, newest.junction, newest.position - b.position, weakest(b.dynamics, newest.dynamics)))
      break;
    binding_.pop_back();
  }
  binding_.push_back(committed_ + index);
}

// The planned entry of the block at ring index i (> 0): its junction's own limit, or less where the machine
// must brake for the next junction that binds downstream, or to stop at the end of the newest block.
double Planner::plannedEntry(size_t i) {
  const long number = committed_ + static_cast<long>(i);
  while (!binding_.empty() && binding_.front() < number) binding_.pop_front();
  const Segment& s = at(i);
  const Segment& newest = at(count_ - 1);
  double entry = s.junction;
  if (!binding_.empty() && binding_.front() != number) {
    const Segment& downstream = at(binding_.front() - committed_);
    entry = cappedReach(entry, downstream.junction, downstream.position - s.position,
                        weakest(s.dynamics, downstream.dynamics));
  }
  return cappedReach(entry, 0.0, nextPosition_ - s.position, weakest(s.dynamics, newest.dynamics));
}

void Planner::commitOldest() {
  Segment& s = at(0);
  const bool hasNext = count_ > 1;
  const double end = s.position + s.length;
  forwardDynamics_ = weakest(forwardDynamics_, s.dynamics);
  const double planned = hasNext ? plannedEntry(1) : 0.0;  // the machine stops at the end of the program
  const double cap = hasNext ? at(1).junction : 0.0;
  const double exit = cappedReach(planned, forwardSpeed_, end - forwardPosition_, forwardDynamics_);
  // LinuxCNC's trapezoids brake block by block where the braking binds: a run that crossed blocks of
  // different accelerations (blend arcs brake at half) would brake at the weakest of them all the way.
  const bool braking = machine_.controller == ControllerKind::LinuxCNC && exit >= planned * (1.0 - 1e-12);
  const bool pinned = !hasNext || exit >= cap * (1.0 - 1e-12) || braking;
  if (pinned) {
    forwardSpeed_ = exit;
    forwardPosition_ = end;
    forwardDynamics_ = hasNext ? at(1).dynamics : s.dynamics;
  }
  if (hasNext) at(1).entry = exit;
  const double entry = s.entry;
  commit_(std::move(s), entry, exit, pinned);  // the ring's slot is left to the next block
  head_ = (head_ + 1) % ring_.size();
  --count_;
  ++committed_;
}

void Planner::finish() {
  if (havePending_) {
    // LinuxCNC keeps a parabolic end on the last line of a blending mode (no next block to blend it with
    // by an arc), and a parabolic blend halves the line's acceleration (tp.c, tpGetScaledAccel).
    const bool parabolicEnd =
        machine_.controller == ControllerKind::LinuxCNC && pending_.block.pathMode != PathMode::ExactStop;
    if (parabolicEnd && !pending_.parabolic) pending_.dynamics.acceleration *= kLinuxCncTangentShare;
    if (pending_.trimmed) lastsACycle(pending_);
    pushPending();
    havePending_ = false;
  }
  while (count_ > 0) commitOldest();
}

}  // namespace hsm::kinematics::detail
