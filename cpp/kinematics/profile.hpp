// Speed profiles along a path: how far and how long a change of speed takes, and the profile of a block.
// The times of speed changes are the physics of kinematics/physics.hpp; distance = mean speed × time.
#pragma once

#include "kinematics/physics.hpp"

namespace hsm::kinematics {

inline double changeTime(double v0, double v1, const Dynamics& d) { return speedChangeTime(std::abs(v1 - v0), d); }
inline double changeDistance(double v0, double v1, const Dynamics& d) { return 0.5 * (v0 + v1) * changeTime(v0, v1, d); }
// The highest speed reachable from v0 (accelerating, or decelerating backwards) within `distance` mm.
double reachableSpeed(double v0, double distance, const Dynamics& d);
// Whether v is reachable from v0 within `distance`, and min(v, reachableSpeed(v0, distance, d)): both
// without solving the cubic of reachableSpeed when v is within reach (the planner's usual case).
inline bool withinReach(double v, double v0, double distance, const Dynamics& d) {
  return v <= v0 || changeDistance(v0, v, d) <= distance;
}
inline double cappedReach(double v, double v0, double distance, const Dynamics& d) {
  return withinReach(v, v0, distance, d) ? v : reachableSpeed(v0, distance, d);
}

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
