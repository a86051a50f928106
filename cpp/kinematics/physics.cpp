#include "kinematics/physics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::kinematics {

double speedChangeTime(double dv, const Dynamics& d) {
  if (dv <= 0.0) return 0.0;
  if (!d.jerkLimited) return dv / d.acceleration;
  const double a = d.acceleration, j = d.jerk;
  return dv <= a * a / j ? 2.0 * std::sqrt(dv / j) : dv / a + a / j;
}

double stopAndGoLoss(double speed, const Dynamics& d) { return speedChangeTime(speed, d); }

double curvatureSpeed(double radius, const Dynamics& d) {
  double v = std::sqrt(d.acceleration * radius);
  if (d.jerkLimited) v = std::min(v, cubeRoot(d.jerk * radius * radius));
  return v;
}

double projectedLimit(const Eigen::Vector3d& limits, const Eigen::Vector3d& u) {
  double result = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) > 1e-12) result = std::min(result, limits[i] / std::abs(u[i]));
  return result;
}

double inPlaneLimit(const Eigen::Vector3d& limits, const Eigen::Vector3d& planeNormal) {
  double result = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double inPlane = std::sqrt(std::max(0.0, 1.0 - planeNormal[i] * planeNormal[i]));
    if (inPlane > 1e-12) result = std::min(result, limits[i] / inPlane);
  }
  return result;
}

bool jerkLimitedByDefault(const MachineModel& machine) {
  return machine.controller == ControllerKind::Siemens840D && machine.jerkLimitedByDefault;
}

Dynamics slowestPlanAxes(const MachineModel& machine) {
  return {std::min(machine.maxAcceleration.x(), machine.maxAcceleration.y()),
          std::min(machine.maxJerk.x(), machine.maxJerk.y()), jerkLimitedByDefault(machine)};
}

}  // namespace hsm::kinematics
