// Machine models as data: what a controller and its axes allow. Read from JSON (resources/machines/).
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hsm::kinematics {

// The machine assumed when none is named: the guidance-curve paper's Mikron UCP 710 with a Siemens 840D.
inline constexpr const char* kDefaultMachine = "mikron-ucp710-840d";

// How the controller plans the path between blocks.
enum class ControllerKind {
  Siemens840D,  // jerk-limited (SOFT) or not (BRISK); G60/G9 exact stop, G64 velocity jumps, G641/G642 rounding
  LinuxCNC,     // trapezoidal; G61 exact stop, G64 tangent blend arcs; a/2 on blendable lines, 0.866·a on arcs
  Grbl,         // trapezoidal; junction deviation; arcs cut into chords
};

struct MachineModel {
  std::string name, description;
  ControllerKind controller = ControllerKind::Siemens840D;
  // Per axis X, Y, Z, in mm/s, mm/s², mm/s³.
  Eigen::Vector3d maxVelocity{500, 500, 500};
  Eigen::Vector3d maxAcceleration{2500, 3000, 2000};
  Eigen::Vector3d maxJerk{5000, 5000, 50000};
  Eigen::Vector3d rapidVelocity{500, 500, 500};   // G0
  Eigen::Vector3d velocityJump{0, 0, 0};         // mm/s an axis may jump at a block junction (840D, LinuxCNC kink)
  double interpolationCycle = 0.004;  // s: a block lasts at least one cycle (block-processing limit)
  int lookAheadBlocks = 100;          // blocks the planner sees ahead; it must be able to stop at the last one
  double cornerTolerance = 0.01;      // mm: rounding (840D G642), blending (LinuxCNC G64 P0), junction deviation (grbl)
  bool jerkLimitedByDefault = true;   // 840D: SOFT at start-up
  double arcTolerance = 0.002;        // mm: grbl cuts arcs into chords within this
  double compressorPathLimit = 20.0;  // mm: 840D compressor, MD20170 COMPRESS_BLOCK_PATH_LIMIT (merging.hpp)
};

// Checks every limit of a model (positive, finite, in a range a machine can have): InputError names the
// field and its unit. The simulator checks the model it is given, since Python may set fields directly.
void checkMachine(const MachineModel& machine);

// Reads a machine model from JSON text; InputError names the missing or bad key and the file.
MachineModel machineFromJson(const std::string& text, const std::string& origin = "machine file");
// Writes the model as JSON in the same keys and units (mm/min for velocities, m/s² and m/s³).
std::string machineToJson(const MachineModel& machine);

std::string controllerName(ControllerKind kind);

// A machine by file path, or by name (NAME.json) in the folders given; InputError lists the names found.
MachineModel loadMachine(const std::string& nameOrFile, const std::vector<std::string>& folders);
// Names of the machine files in the folders, sorted.
std::vector<std::string> machineNames(const std::vector<std::string>& folders);

}  // namespace hsm::kinematics
