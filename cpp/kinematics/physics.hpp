// The machine's physics along a path, written once: how long a change of speed takes (S-curve or
// trapezoid), the steady speed a curve allows, and the per-axis limits projected onto a direction.
// The feed-rate planner (kinematics/planner.cpp) and the machining-direction model (direction/) use it.
//
// Every speed change starts and ends at zero acceleration. Jerk-limited (840D SOFT): the acceleration ramps
// at J up to A (if reached) and back, so Δv ≤ A²/J takes 2·sqrt(Δv/J) and larger changes Δv/A + A/J;
// acceleration-limited (840D BRISK, LinuxCNC, grbl): steps of A, Δv/A. On radius R the steady speed is
// at most sqrt(A·R), and cbrt(J·R²) when jerk-limited. Per-axis limits l_i project on a unit direction u
// as min_i l_i/|u_i|.
#pragma once

#include "kinematics/machine.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace hsm::kinematics {

struct Dynamics {
  double acceleration = 0.0;  // A, mm/s², along the path
  double jerk = 0.0;          // J, mm/s³, along the path; ignored when !jerkLimited
  bool jerkLimited = true;
};

// The real cube root to within an ulp or two, about 8 times cheaper than std::cbrt (glibc's goes through
// frexp and ldexp): the simulator takes two per reachable speed and was spending 15 % of its time there.
// A bit-level first guess (within 4 %) and three Halley steps (cubic convergence: 4e-2, 1e-5, 1e-16).
inline double cubeRoot(double x) {
  if (!(std::isfinite(x)) || x == 0.0) return std::cbrt(x);
  const double a = std::abs(x);
  std::uint64_t bits;
  std::memcpy(&bits, &a, sizeof bits);
  bits = bits / 3 + 0x2A9F7893782DA1CEull;
  double y;
  std::memcpy(&y, &bits, sizeof y);
  for (int i = 0; i < 3; ++i) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * a) / (2.0 * y3 + a);
  }
  return x < 0.0 ? -y : y;
}

// (The small functions are inline: the planner calls them for every block.)

// Time of a speed change by Δv ≥ 0 (0 for Δv ≤ 0).
inline double speedChangeTime(double dv, const Dynamics& d) {
  if (dv <= 0.0) return 0.0;
  if (!d.jerkLimited) return dv / d.acceleration;
  const double a = d.acceleration, j = d.jerk;
  return dv <= a * a / j ? 2.0 * std::sqrt(dv / j) : dv / a + a / j;
}

// The time a stop from `speed` and a start back to it cost over cruising through the same distance: the
// braking and the start each cover speed·t/2 in t, so together they lose one change time t.
inline double stopAndGoLoss(double speed, const Dynamics& d) { return speedChangeTime(speed, d); }

// Highest steady speed on a curve of radius `radius` mm.
inline double curvatureSpeed(double radius, const Dynamics& d) {
  const double v = std::sqrt(d.acceleration * radius);
  // The jerk's bound (J·r²)^(1/3) is only solved for where it is the lower: v³ > J·r².
  return d.jerkLimited && v * v * v > d.jerk * radius * radius ? std::min(v, cubeRoot(d.jerk * radius * radius)) : v;
}

// min over the axes of limits_i / |u_i|: per-axis limits projected on direction u (infinite for u = 0).
inline double projectedLimit(const Eigen::Vector3d& limits, const Eigen::Vector3d& u) {
  double result = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) > 1e-12) result = std::min(result, limits[i] / std::abs(u[i]));
  return result;
}

// Per-axis limits within a plane (unit normal n): the radius of the largest circle about the origin inside
// the box of the limits, cut by the plane, min over the axes of limits_i / sqrt(1 − n_i²) (axes along n
// ignored). What a curve in that plane may count on in every direction across it: LinuxCNC's
// calculateInscribedDiameter for its blend arcs. Infinite for n = 0.
double inPlaneLimit(const Eigen::Vector3d& limits, const Eigen::Vector3d& planeNormal);

// Whether the controller limits the jerk of the path by default (840D SOFT at start-up; LinuxCNC and grbl
// are trapezoidal).
bool jerkLimitedByDefault(const MachineModel& machine);

// The acceleration and jerk of the slowest of the X and Y axes: what a path in any plan direction may
// count on (the a_max of Quinsat & Sabourin's machining-direction model).
Dynamics slowestPlanAxes(const MachineModel& machine);

}  // namespace hsm::kinematics
