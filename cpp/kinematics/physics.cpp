#include "kinematics/physics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::kinematics {

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
