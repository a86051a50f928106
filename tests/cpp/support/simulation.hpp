// Shared by the kinematics tests: the machine presets of resources/machines, and a program given as text
// simulated with its per-block results kept.
#pragma once

#include "kinematics/simulation.hpp"

#include <sstream>
#include <string>

namespace hsm::test {

inline kinematics::MachineModel preset(const std::string& name) {
  return kinematics::loadMachine(name, {HSM_MACHINES_DIR});
}

inline kinematics::SimulationResult run(const std::string& program, const kinematics::MachineModel& machine) {
  std::istringstream stream(program);
  kinematics::SimulationOptions options;
  options.keepBlocks = true;
  return kinematics::simulate(stream, machine, {}, options);
}

}  // namespace hsm::test
