// How a block of a 4- or 5-axis program moves the machine's axes (internal to the simulator).
//
// The controller interpolates the block in one parameter, and every axis follows: with the tool tip programmed
// (840D TRAORI, LinuxCNC with TCP kinematics) the tip moves on the programmed line in the workpiece frame and the
// orientation turns with it — rotary axes linearly (as programmed A B C, ORIAXES/ORIMKS), or the tool axis on the
// great circle between the two vectors (A3 B3 C3 with ORIWKS/ORIVECT) with the angles from the inverse
// kinematics — and X Y Z are what the chain needs; with machine axes programmed every axis moves linearly.
// F is the speed of the tool tip (tip programmed) or of X Y Z (machine axes); when only rotary axes move it is
// in deg/min along their combined angle, as both controllers read it.
//
// A block is cut where its axes' rates change: each piece carries, per axis, d(axis)/ds and d²(axis)/ds² along
// the feed's path s, from which the planner projects each axis's velocity, acceleration and jerk limits (and the
// speed at which the rate's change needs the whole acceleration), as the 3-axis model projects X, Y and Z.
#pragma once

#include "kinematics/five_axis.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/machine.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace hsm::kinematics {

// What limits the speed of a block: the feed, an axis (its velocity, or its acceleration where the block is too
// short or the axis's rate turns), the path's curvature or the block rate. Reported per block and summed in time.
enum class SpeedLimit { Feed, X, Y, Z, A, B, C, Curvature, BlockRate };
inline constexpr int kSpeedLimitCount = 9;
const char* speedLimitName(SpeedLimit limit);

using JointVector = Eigen::Matrix<double, 5, 1>;  // X Y Z (mm) and the rotary axes in chain order (deg)

struct JointMotion {
  bool active = false;
  double pathLength = 0.0;  // along the feed's path: mm, or deg when only rotary axes move
  double tipLength = 0.0;   // mm of tool-tip path in the workpiece frame
  bool rotaryOnly = false;  // the block moves rotary axes only: F and s are in degrees
  JointVector rate = JointVector::Zero();       // d(axis)/ds
  JointVector curvature = JointVector::Zero();  // d²(axis)/ds², the largest at the piece's two ends
  JointVector start = JointVector::Zero(), end = JointVector::Zero();  // machine axes at the piece's ends
};

// At most this many pieces per block (one per degree of the largest rotary move, per 1/50 of the tip's turn of
// orientation): a block swinging 360° is bounded work.
inline constexpr int kMaxPiecesPerBlock = 720;

// The machine's angles before the first block (0), updated as blocks are cut.
class FiveAxisCutter {
public:
  explicit FiveAxisCutter(const MachineModel& machine) : machine_(machine) {}
  // Cuts `block` into pieces, each a Block (tool-tip ends in the workpiece frame) with its joint motion.
  // InputError (with the block's line) when the machine cannot take the orientation or a rotary axis the
  // program moves.
  void cut(const Block& block, const std::function<void(const Block&, const JointMotion&)>& piece);
  // Whether the block turns a rotary axis (or gives an orientation) where the program left them.
  bool turns(const Block& block) const {
    return block.orientationVectors || block.rotaryEnd != programmed_;
  }

private:
  JointVector jointsAt(const Block& block, double lambda);
  // LinuxCNC's planner: the block as one piece in the program's coordinates (see RotaryPlanner::LinuxCnc).
  void programPiece(const Block& block, const std::function<void(const Block&, const JointMotion&)>& piece);
  // The machine axes at `pieces` + 1 points, refined near singularities (pieces may grow).
  void sample(const Block& block, const RotaryAngles& startAngles, int& pieces, std::vector<JointVector>& q);
  JointVector startJoints(const Block& block, const RotaryAngles& angles);
  void onePiece(const Block& block, const JointVector& q0, const JointVector& q1,
                const std::function<void(const Block&, const JointMotion&)>& piece);
  void ended(const Block& block, const JointVector& joints);
  void remember(const Block& block, const Eigen::Vector3d& end, const JointVector& joints);
  const MachineModel& machine_;
  RotaryAngles previous_{0.0, 0.0};
  // Where the last block cut ended: its point as programmed and the machine's axes there (a next block that starts
  // there at the same angles starts there).
  bool endKnown_ = false, endTip_ = false;
  Eigen::Vector3d endPoint_ = Eigen::Vector3d::Zero();
  JointVector endJoints_ = JointVector::Zero();
  // Scratch of cut(), kept so that a block allocates nothing.
  std::vector<JointVector> q_, rate_, bend_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<double> ds_, tipLength_;
  // Where the previous block left the program: A B C as programmed, the tool axis (zero: the angles' own).
  Eigen::Vector3d programmed_ = Eigen::Vector3d::Zero(), orientation_ = Eigen::Vector3d::Zero();
  RotaryAngles fromAngles_{0.0, 0.0}, toAngles_{0.0, 0.0};  // the block's angles when the axes interpolate
};

}  // namespace hsm::kinematics
