// Machine models as data: what a controller and its axes allow. Read from JSON (resources/machines/).
#pragma once

#include "kinematics/dialect.hpp"

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

// How blocks that turn rotary axes are planned.
enum class RotaryPlanner {
  // Every axis of the machine (X Y Z after the kinematics, and the rotary axes) is followed along the block and
  // held to its own limits: the 840D's TRAORI, and any machine whose controller plans in joint space.
  JointSpace,
  // LinuxCNC 2.9: the program's own coordinates (tool tip X Y Z, A B C linear) are planned with the [AXIS_*]
  // limits, joint limits unchecked in coordinated motion; a block that turns a rotary axis is never blended or
  // looked ahead through: it runs from rest to rest, overlapped with its neighbours by a parabolic blend.
  LinuxCnc,
};

// A rotary axis of a 4- or 5-axis machine. Positions in degrees, as programmed; limits in deg/s, deg/s², deg/s³
// (files hold deg/min, deg/s², deg/s³: the units of machine data sheets).
struct RotaryAxis {
  char name = 'C';                                       // A, B or C
  bool onTable = true;                                   // carried by the table (turns the workpiece) or the head
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // at zero angles, machine frame; positive turns right-handed
  // A point of the axis at zero angles: on the table, in machine coordinates (the workpiece frame is the machine
  // frame at zero angles); on the head, from the tool tip (a fork head's pivot length is the Z of this point).
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  double maxVelocity = 360.0, maxAcceleration = 720.0, maxJerk = 7200.0, rapidVelocity = 360.0;
  double minPosition = -360.0, maxPosition = 360.0;      // deg, travel
  bool continuous = false;                               // no travel limits (a C table that turns for ever)
  bool limitsTravel() const { return !continuous; }
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
  // Rotary axes in the order of the kinematic chain: the table's from the bed outwards, then the head's from the
  // ram to the spindle; none for a 3-axis machine, one for a 4-axis, two for a 5-axis. The tool points along
  // `toolAxis` (tip to spindle, machine frame) at zero angles.
  std::vector<RotaryAxis> rotaryAxes;
  Eigen::Vector3d toolAxis = Eigen::Vector3d::UnitZ();
  // X Y Z of the program are the tool tip in the workpiece frame without a word saying so (LinuxCNC with TCP
  // kinematics such as xyzac-trt-kins); the 840D's programs switch it with TRAORI / TRAFOOF.
  bool toolTipProgrammed = false;
  RotaryPlanner rotaryPlanner = RotaryPlanner::JointSpace;  // how blocks that turn rotary axes are planned
  // The program's dialect and what the control assumes where a program says nothing (dialect.hpp); the
  // dialect follows the controller unless the file names one (a Fanuc or Haas control plans as `controller`).
  ControlConventions conventions{Dialect::Siemens840D, "", false, Eigen::Vector3d::Zero(), 0.01};

  bool hasRotaryAxes() const { return !rotaryAxes.empty(); }
  // "table-table", "head-table", "head-head", "table" or "head" (4 axes), "" (3 axes).
  std::string kinematicsName() const;
  // Index in rotaryAxes of the axis named A, B or C; −1 when the machine has none.
  int rotaryIndex(char name) const;
};

// Checks every limit of a model (positive, finite, in a range a machine can have): InputError names the
// field and its unit. The simulator checks the model it is given, since Python may set fields directly.
void checkMachine(const MachineModel& machine);
// The rotary axes' part of checkMachine: at most two, not parallel, table axes before head axes, limits in range.
void checkRotaryAxes(const MachineModel& machine);

// Reads a machine model from JSON text; InputError names the missing or bad key and the file.
MachineModel machineFromJson(const std::string& text, const std::string& origin = "machine file");
// Writes the model as JSON in the same keys and units (mm/min for velocities, m/s² and m/s³).
std::string machineToJson(const MachineModel& machine);

std::string controllerName(ControllerKind kind);
std::string rotaryPlannerName(RotaryPlanner planner);  // "joint-space" or "linuxcnc", as in the JSON file

// A machine by file path, or by name (NAME.json) in the folders given; InputError lists the names found.
MachineModel loadMachine(const std::string& nameOrFile, const std::vector<std::string>& folders);
// Names of the machine files in the folders, sorted.
std::vector<std::string> machineNames(const std::vector<std::string>& folders);

}  // namespace hsm::kinematics
