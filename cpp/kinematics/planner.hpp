// Internal: the look-ahead planner. Blocks go in; each comes out once its entry and exit speeds are final.
//
// Junction speeds come from a backward pass (the machine must be able to stop at the end of the last block
// it sees) and a forward pass (what it can reach from the last point where the speed was pinned), each
// following one S-curve from the binding constraint over the whole distance, not one per block: chaining a
// zero-acceleration S-curve per short block would make accelerating over a chain of short blocks far
// slower than any controller. A junction is pinned when its speed is its own limit (a corner, a stop, the
// start and the end); the motion between two pinned junctions is timed as one run (runs.hpp).
#pragma once

#include "kinematics/five_axis_motion.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/machine.hpp"
#include "kinematics/profile.hpp"

#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace hsm::kinematics::detail {

struct Segment {
  Block block;
  long source = 0;          // index of the program block (several segments when grbl cuts an arc)
  double length = 0.0;
  double programmed = 0.0;  // mm/s: F, or the rapid speed projected on the block
  double cruise = 0.0;      // mm/s: the most the block allows
  double junction = 0.0;    // mm/s: the most the junction with the previous block allows (0 for the first)
  Dynamics dynamics;
  double position = 0.0;    // mm: distance along the program at the start of the block
  double entry = 0.0;       // entry speed, final once the block before it is committed
  bool kinkScaled = false;  // LinuxCNC G61: the acceleration already lost its kink share
  bool parabolic = false;   // LinuxCNC: a parabolic blend at one of its ends halved its acceleration
  // s after the block before the next starts: at rest (LinuxCNC: a servo cycle at each exact stop), or, when
  // negative, the time the next block starts before this one ends (LinuxCNC's parabolic blend)
  double restAfter = 0.0;
  bool parabolicFromPrevious = false;  // LinuxCNC: overlapped with the block before it by a parabolic blend
  bool trimmed = false;     // LinuxCNC: a blend arc took the start of the block
  // LinuxCNC's blend arc, a segment of the block before the corner: `block` holds the arc's chord (traces),
  // these the block's programmed ends (reports).
  bool blendArc = false;
  Eigen::Vector3d programmedStart = Eigen::Vector3d::Zero(), programmedEnd = Eigen::Vector3d::Zero();
  Eigen::Vector3d startTangent, endTangent;
  // 4- and 5-axis blocks: how the machine's axes move along it; none for a 3-axis block (shared, not held by
  // value: the segment is copied along the planner, and a 3-axis program must not pay for the 5-axis data).
  std::shared_ptr<const JointMotion> joint;
  SpeedLimit limit = SpeedLimit::Feed;   // what sets `cruise`
  SpeedLimit accelerationLimit = SpeedLimit::X;  // 5 axes: the axis whose acceleration bounds the piece's
};

// A corner of deflection φ in the half-angle terms its blends need, from cos φ alone (no acos, cos, tan:
// they were a tenth of the simulation's time).
struct Corner {
  double cosHalf, sinHalf, tanHalf, sinPhi;
  explicit Corner(double cosine)
      : cosHalf(std::sqrt(0.5 * (1.0 + cosine))), sinHalf(std::sqrt(0.5 * (1.0 - cosine))),
        tanHalf(sinHalf / cosHalf), sinPhi(2.0 * sinHalf * cosHalf) {}
};


// The weaker of two dynamics: a run over blocks of different directions obeys the weakest of them.
Dynamics weakest(const Dynamics& a, const Dynamics& b);

class Planner {
public:
  // A block with its final entry and exit speeds; pinnedExit: the exit speed is the junction's own limit.
  using Commit = std::function<void(Segment&&, double entry, double exit, bool pinnedExit)>;  // the segment is given away
  Planner(const MachineModel& machine, Commit commit);

  void add(const Block& block, long source, const JointMotion* joint = nullptr);
  void finish();  // the machine stops at the end of the last block

private:
  struct Junction {
    double speed = 0.0;                                          // the most the junction allows
    double adjacentCap = std::numeric_limits<double>::infinity();  // the most both blocks allow when the
                                                                 // junction is really a curve (short blocks)
    // LinuxCNC's blend arc, a segment of its own between the blocks: the tangent length R·tan(φ/2) it takes
    // from each block (0: no arc), its length R·φ and its acceleration along the path.
    double trim = 0.0, arcLength = 0.0, arcAcceleration = 0.0;
    double kinkShare = 0.0;  // LinuxCNC tangent kink: the share of acceleration both blocks give up for it
    bool parabolic = false;  // LinuxCNC: no arc could be made; a parabolic blend halves both accelerations
    // LinuxCNC: a block turning a rotary axis meets the other: both run from rest to rest, the block before
    // at half its acceleration, the next one starting as it brakes (G64; G61 stops at full acceleration)
    bool rotaryStop = false;
  };
  Segment prepare(const Block& block, long source, const JointMotion* joint) const;
  // Limits of a piece of a 4- or 5-axis block from each axis's rate along the path (five_axis_motion.hpp).
  void jointLimits(Segment& s, const JointMotion& joint, double& velocity, double& rapidVelocity,
                   double& curvatureLimit) const;
  SpeedLimit slowestAxis(const JointVector& inverseLimits, const Eigen::Vector3d& tangent) const;
  Junction junction(const Segment& before, const Segment& after) const;
  Junction tipJunction(const Segment& before, const Segment& after) const;
  Junction jointJunction(const Segment& before, const Segment& after) const;
  double linuxCncKink(const Segment& before, const Segment& after, double v) const;
  void linuxCncExactStop(Segment& before, Segment& after) const;
  double linuxCncCorner(const Segment& before, const Segment& after, const Corner& corner, double cosine,
                        double limit, Junction& j) const;
  void push(Segment&& segment);  // the segment is moved into the ring once
  void overlapParabolic(Segment& before, const Segment& after) const;
  void pushPending();
  void lastsACycle(Segment& s) const;
  Segment blendArc(const Segment& before, const Segment& after, const Junction& j) const;
  void commitOldest();
  double plannedEntry(size_t i);
  Segment& at(size_t i) { return ring_[(head_ + i) % ring_.size()]; }

  const MachineModel& machine_;
  JointVector jointVelocity_, jointRapid_, jointAcceleration_, jointJerk_;  // X Y Z and the rotary axes
  JointVector inverseVelocity_, inverseRapid_, inverseAcceleration_, inverseJerk_;  // 1 / each
  Commit commit_;
  std::vector<Segment> ring_;
  size_t head_ = 0, count_ = 0;
  bool havePending_ = false;
  Segment pending_;  // the newest block, until its successor (and so its own junction caps) is known
  double nextPosition_ = 0.0;
  long committed_ = 0;              // blocks committed so far: ring index i is block committed_ + i
  std::deque<long> binding_;        // blocks (by number) whose entry junction binds, oldest first
  // Forward pass: the last pinned junction and the weakest dynamics since.
  double forwardSpeed_ = 0.0, forwardPosition_ = 0.0;
  Dynamics forwardDynamics_{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), false};
};

}  // namespace hsm::kinematics::detail
