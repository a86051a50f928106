// Speed profiles along a path: how far and how long a change of speed takes, with or without a jerk limit.
//
// Every speed change starts and ends at zero acceleration. Jerk-limited (840D SOFT): the acceleration
// ramps at J up to A (if reached) and back; acceleration-limited (840D BRISK, LinuxCNC, grbl): steps of A.
// Δv ≤ A²/J is reached in 2·sqrt(Δv/J), larger changes in Δv/A + A/J; distance = mean speed × time.
#pragma once

namespace hsm::kinematics {

struct Dynamics {
  double acceleration = 0.0;  // A, mm/s², along the path
  double jerk = 0.0;          // J, mm/s³, along the path; ignored when !jerkLimited
  bool jerkLimited = true;
};

double changeTime(double v0, double v1, const Dynamics& d);
double changeDistance(double v0, double v1, const Dynamics& d);
// The highest speed reachable from v0 (accelerating, or decelerating backwards) within `distance` mm.
double reachableSpeed(double v0, double distance, const Dynamics& d);

// The profile of one block: from v0 up to the peak, cruise at the peak, down to v1.
struct BlockProfile {
  double time = 0.0;   // s
  double peak = 0.0;   // mm/s, highest speed in the block
  double v0 = 0.0, v1 = 0.0;
  double accelTime = 0.0, cruiseTime = 0.0, decelTime = 0.0;
};

// Profile for a block of length L entered at v0 and left at v1, cruising at most at vCruise. Requires
// v0, v1 ≤ vCruise and |v1 − v0| reachable within L (the planner guarantees both).
BlockProfile blockProfile(double length, double v0, double v1, double vCruise, const Dynamics& d);

// State (distance, speed) `t` seconds into a profile, for time-sampled traces.
struct ProfileState {
  double distance = 0.0, speed = 0.0;
};
ProfileState stateAt(const BlockProfile& profile, double t, const Dynamics& d);

}  // namespace hsm::kinematics
