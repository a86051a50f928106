// Forward and inverse kinematics of 4- and 5-axis machines (MachineModel::rotaryAxes): tool tip and tool axis in
// the workpiece frame <-> machine axes X Y Z and the rotary axes.
//
// The chain is written as a product of exponentials on the zero configuration (the workpiece frame is the machine
// frame at zero angles): each rotary axis turns about its direction through its pivot, both given at zero angles,
// so a table A/C trunnion, a head B with a table C and a fork head are the same code with other data.
//   workpiece point p  ->  machine point  T₁(θ₁) ∘ T₂(θ₂) … (p)       (table axes, bed outwards)
//   tool tip at zero   ->  tip            X Y Z + H₁(φ₁) ∘ H₂(φ₂) …(0)  (head axes, ram to spindle; 0 is the tip)
// LinuxCNC's xyzac-trt-kins is this with A about +X through (x, y + y-offset, z + z-offset) of its rot-point and C
// about +Z through the rot-point, both turning as its default "non-conventional" directions do.
#pragma once

#include "kinematics/machine.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace hsm::kinematics {

using RotaryAngles = std::array<double, 2>;  // deg, the rotary axes in chain order (the second unused on 4 axes)

struct ToolPose {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();         // mm, workpiece frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();       // unit, from the tip towards the spindle
};

struct MachinePosition {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();  // X Y Z, mm
  RotaryAngles angles{0.0, 0.0};                     // deg
};

// Tool tip and axis in the workpiece frame for machine axes.
ToolPose forwardKinematics(const MachineModel& machine, const MachinePosition& position);
// The tool axis in the workpiece frame at these angles.
Eigen::Vector3d toolAxisAt(const MachineModel& machine, const RotaryAngles& angles);
// X Y Z that put the tool tip on `tip` (workpiece frame) at these angles.
Eigen::Vector3d linearAxesFor(const MachineModel& machine, const Eigen::Vector3d& tip, const RotaryAngles& angles);

// One set of angles that orients the tool, in (−180°, 180°]. Singular: the tool axis lies on a rotary axis's
// line (A = 0 on an A/C trunnion), so that axis's angle is free; it is left at 0 here.
struct AngleSolution {
  RotaryAngles angles{0.0, 0.0};
  std::array<bool, 2> free{false, false};  // the angle of this axis does not change the orientation
};
// Every solution for a tool axis (workpiece frame): none when the machine cannot point the tool that way, one
// at a singularity or on a 4-axis machine, two otherwise.
std::vector<AngleSolution> orientationSolutions(const MachineModel& machine, const Eigen::Vector3d& axis);

struct InverseResult {
  MachinePosition position;
  bool singular = false;  // an angle was free and kept its previous value
  int solutions = 0;      // how many solutions the orientation had (before the travel check)
};
// The machine position for a pose: among the solutions (each axis's angle taken at the turn nearest to its
// previous value, every turn tried for the travel), the one within travel nearest to `previous` (least sum of
// angle changes); a free angle keeps its previous value. InputError when the machine cannot reach the
// orientation, or no solution lies within travel (it names the axis and its travel).
InverseResult inverseKinematics(const MachineModel& machine, const ToolPose& pose, const RotaryAngles& previous);

// How far a tool axis may be off the machine's reach (unit vectors) and still be taken as reachable.
inline constexpr double kOrientationTolerance = 1e-7;

}  // namespace hsm::kinematics
