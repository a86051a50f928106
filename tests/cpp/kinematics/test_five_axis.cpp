#include "common/error.hpp"
#include "kinematics/five_axis.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

using namespace hsm::kinematics;

namespace {
MachineModel preset(const std::string& name) { return loadMachine(name, {HSM_MACHINES_DIR}); }
constexpr double kDeg = M_PI / 180.0;

// LinuxCNC 2.9's xyzac-trt inverse kinematics, written out from its documented formulas (rot-point 0): the
// joints X Y Z for a tool tip (x, y, z) of the workpiece at angles a, c with y-offset dy and z-offset dz.
Eigen::Vector3d linuxCncTrtJoints(const Eigen::Vector3d& p, double a, double c, double dy, double dz) {
  a *= kDeg, c *= kDeg;
  return {std::cos(c) * p.x() - std::sin(c) * p.y(),
          std::sin(c) * std::cos(a) * p.x() + std::cos(c) * std::cos(a) * p.y() - std::sin(a) * p.z() -
              std::cos(a) * dy + std::sin(a) * dz + dy,
          std::sin(c) * std::sin(a) * p.x() + std::cos(c) * std::sin(a) * p.y() + std::cos(a) * p.z() -
              std::sin(a) * dy - std::cos(a) * dz + dz};
}

MachineModel withAxes(std::vector<RotaryAxis> axes) {
  MachineModel m;
  m.name = "test";
  m.rotaryAxes = std::move(axes);
  return m;
}

RotaryAxis axis(char name, bool table, Eigen::Vector3d direction, Eigen::Vector3d pivot = Eigen::Vector3d::Zero()) {
  RotaryAxis a;
  a.name = name;
  a.onTable = table;
  a.direction = direction;
  a.pivot = pivot;
  a.continuous = true;
  return a;
}
}  // namespace

TEST(FiveAxis, PresetsDescribeTheirChains) {
  EXPECT_EQ(preset("linuxcnc-2.9-xyzac-trt").kinematicsName(), "table-table");
  EXPECT_EQ(preset("mikron-ucp710-ac-840d").kinematicsName(), "table-table");
  EXPECT_EQ(preset("swivel-head-bc-840d").kinematicsName(), "head-table");
  EXPECT_EQ(preset("mikron-ucp710-840d").kinematicsName(), "");
  const MachineModel trt = preset("linuxcnc-2.9-xyzac-trt");
  EXPECT_NEAR(trt.rotaryAxes[0].maxVelocity, 30.0, 1e-12);  // deg/s from 1800 deg/min
  EXPECT_EQ(trt.rotaryAxes[0].minPosition, -100.0);
  EXPECT_TRUE(trt.rotaryAxes[1].continuous);
  // Written back and read again, the model is the same.
  const MachineModel again = machineFromJson(machineToJson(trt));
  ASSERT_EQ(again.rotaryAxes.size(), 2u);
  EXPECT_EQ(again.rotaryAxes[0].pivot, trt.rotaryAxes[0].pivot);
  EXPECT_EQ(again.rotaryAxes[1].name, 'C');
}

TEST(FiveAxis, TrunnionMatchesLinuxCncXyzacTrt) {
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-80, 80), a(-100, 50), c(-720, 720);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d tip(coordinate(random), coordinate(random), coordinate(random));
    const RotaryAngles angles{a(random), c(random)};
    const Eigen::Vector3d joints = linearAxesFor(m, tip, angles);
    EXPECT_LT((joints - linuxCncTrtJoints(tip, angles[0], angles[1], 20.0, 10.0)).norm(), 1e-9);
    const ToolPose pose = forwardKinematics(m, {joints, angles});
    EXPECT_LT((pose.tip - tip).norm(), 1e-9);
  }
  // A = 30: the tool leans towards +Y of the workpiece.
  EXPECT_LT((toolAxisAt(m, {30.0, 0.0}) - Eigen::Vector3d(0, 0.5, std::sqrt(0.75))).norm(), 1e-12);
}

TEST(FiveAxis, InverseOfForwardOnEveryFiveAxisPreset) {
  std::mt19937 random(11);
  for (const char* name : {"linuxcnc-2.9-xyzac-trt", "mikron-ucp710-ac-840d", "swivel-head-bc-840d"}) {
    const MachineModel m = preset(name);
    for (int k = 0; k < 300; ++k) {
      MachinePosition position;
      for (int i = 0; i < 3; ++i) position.linear[i] = std::uniform_real_distribution<double>(-200, 200)(random);
      for (int i = 0; i < 2; ++i) {
        const RotaryAxis& a = m.rotaryAxes[i];
        position.angles[i] = a.continuous ? std::uniform_real_distribution<double>(-400, 400)(random)
                                          : std::uniform_real_distribution<double>(a.minPosition, a.maxPosition)(random);
      }
      const ToolPose pose = forwardKinematics(m, position);
      // Started next to the true angles, the inverse finds them again (not the other solution).
      const RotaryAngles previous{position.angles[0] + 0.5, position.angles[1] - 0.5};
      const InverseResult inverse = inverseKinematics(m, pose, previous);
      if (inverse.singular) continue;
      EXPECT_NEAR(inverse.position.angles[0], position.angles[0], 1e-6) << name;
      EXPECT_NEAR(inverse.position.angles[1], position.angles[1], 1e-6) << name;
      EXPECT_LT((inverse.position.linear - position.linear).norm(), 1e-6) << name;
      // Every solution gives the pose back.
      for (const AngleSolution& s : orientationSolutions(m, pose.axis)) {
        EXPECT_LT((toolAxisAt(m, s.angles) - pose.axis).norm(), 1e-9) << name;
        const ToolPose back = forwardKinematics(m, {linearAxesFor(m, pose.tip, s.angles), s.angles});
        EXPECT_LT((back.tip - pose.tip).norm(), 1e-9) << name;
      }
    }
  }
}

TEST(FiveAxis, TwoSolutionsAndTheNearestIsChosen) {
  const MachineModel m = preset("mikron-ucp710-ac-840d");
  ToolPose pose;
  pose.axis = Eigen::Vector3d(0, 0.5, std::sqrt(0.75));
  const auto solutions = orientationSolutions(m, pose.axis);
  ASSERT_EQ(solutions.size(), 2u);
  const RotaryAngles nearest = inverseKinematics(m, pose, {0, 0}).position.angles;
  EXPECT_NEAR(nearest[0], 30.0, 1e-9);
  EXPECT_NEAR(nearest[1], 0.0, 1e-9);
  // From near the other solution (A = −30, C = 180) the machine stays there.
  const RotaryAngles other = inverseKinematics(m, pose, {-20, 170}).position.angles;
  EXPECT_NEAR(other[0], -30.0, 1e-9);
  EXPECT_NEAR(other[1], 180.0, 1e-9);
  // C is continuous: from C = 350 the same orientation is taken at C = 360, not back at 0.
  EXPECT_NEAR(inverseKinematics(m, pose, {25, 350}).position.angles[1], 360.0, 1e-9);
}

TEST(FiveAxis, SingularityKeepsC) {
  // A = 0 on an A/C trunnion: the tool lies on C's axis, any C gives the same orientation.
  const MachineModel m = preset("mikron-ucp710-ac-840d");
  ToolPose pose;
  pose.tip = Eigen::Vector3d(10, 20, 5);
  pose.axis = Eigen::Vector3d::UnitZ();
  const InverseResult result = inverseKinematics(m, pose, {3.0, 37.0});
  EXPECT_TRUE(result.singular);
  EXPECT_NEAR(result.position.angles[0], 0.0, 1e-9);
  EXPECT_EQ(result.position.angles[1], 37.0);
  EXPECT_LT((forwardKinematics(m, result.position).tip - pose.tip).norm(), 1e-9);
}

TEST(FiveAxis, TravelAndReachAreChecked) {
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");  // A from −100 to 50
  ToolPose down;
  down.axis = -Eigen::Vector3d::UnitZ();  // |A| = 180 on both solutions
  try {
    inverseKinematics(m, down, {0, 0});
    FAIL() << "a tool pointing up from under the table was accepted";
  } catch (const hsm::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("A [-100, 50] deg"), std::string::npos) << error.what();
  }
  // A = 70 is out of travel, its twin A = −70 with C turned half a turn is in: that one is taken.
  ToolPose leaning;
  leaning.axis = toolAxisAt(m, {70.0, 0.0});
  const RotaryAngles angles = inverseKinematics(m, leaning, {0, 0}).position.angles;
  EXPECT_NEAR(angles[0], -70.0, 1e-9);
  EXPECT_NEAR(std::abs(angles[1]), 180.0, 1e-9);
}

TEST(FiveAxis, HeadTableSwivelsAboutItsPivot) {
  const MachineModel m = preset("swivel-head-bc-840d");  // B about Y, 300 mm above the tip
  const Eigen::Vector3d tip(10, 20, 30);
  const Eigen::Vector3d linear = linearAxesFor(m, tip, {0.0, 90.0});
  // The head swung by 90° carries the tip 300 mm along −X and up 300 mm from the pivot: the axes make up for it.
  EXPECT_LT((linear - (tip + Eigen::Vector3d(300, 0, -300))).norm(), 1e-9);
  EXPECT_LT((toolAxisAt(m, {0.0, 90.0}) - Eigen::Vector3d::UnitX()).norm(), 1e-12);
  // C turns the workpiece: the same machine-frame tool axis is another workpiece-frame axis.
  EXPECT_LT((toolAxisAt(m, {90.0, 90.0}) - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);
}

TEST(FiveAxis, FourAxisMachineReachesOneCone) {
  const MachineModel m = withAxes({axis('A', true, Eigen::Vector3d::UnitX())});
  EXPECT_EQ(m.kinematicsName(), "table");
  ToolPose pose;
  pose.axis = Eigen::Vector3d(0, -std::sqrt(0.5), std::sqrt(0.5));  // in the YZ plane: reachable
  ASSERT_EQ(orientationSolutions(m, pose.axis).size(), 1u);
  EXPECT_NEAR(inverseKinematics(m, pose, {0, 0}).position.angles[0], -45.0, 1e-9);
  EXPECT_TRUE(orientationSolutions(m, Eigen::Vector3d(0.6, 0, 0.8)).empty());  // leans along A's axis: no
  EXPECT_THROW(inverseKinematics(m, {{0, 0, 0}, {0.6, 0, 0.8}}, {0, 0}), hsm::InputError);
}

TEST(FiveAxis, HeadHeadForkMatchesItsRotations) {
  // C head about Z, A fork about X 200 mm above the tip.
  const MachineModel m = withAxes({axis('C', false, Eigen::Vector3d::UnitZ()),
                                    axis('A', false, Eigen::Vector3d::UnitX(), Eigen::Vector3d(0, 0, 200))});
  EXPECT_EQ(m.kinematicsName(), "head-head");
  const RotaryAngles angles{40.0, 25.0};
  const Eigen::Vector3d expected = Eigen::AngleAxisd(40 * kDeg, Eigen::Vector3d::UnitZ()) *
                                   (Eigen::AngleAxisd(25 * kDeg, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ());
  EXPECT_LT((toolAxisAt(m, angles) - expected).norm(), 1e-12);
  const InverseResult back = inverseKinematics(m, {{1, 2, 3}, expected}, {35.0, 20.0});
  EXPECT_NEAR(back.position.angles[0], 40.0, 1e-9);
  EXPECT_NEAR(back.position.angles[1], 25.0, 1e-9);
}

TEST(FiveAxis, BadRotaryAxesAreRefusedByName) {
  const std::string head = R"({"name": "m", "controller": "siemens-840d", "interpolation_cycle_ms": 4,
    "look_ahead_blocks": 100, "corner_tolerance_mm": 0.01, "axes": {
    "X": {"max_velocity_mm_min": 1000, "max_acceleration_m_s2": 1, "max_jerk_m_s3": 5, "rapid_velocity_mm_min": 1000, "velocity_jump_mm_min": 0},
    "Y": {"max_velocity_mm_min": 1000, "max_acceleration_m_s2": 1, "max_jerk_m_s3": 5, "rapid_velocity_mm_min": 1000, "velocity_jump_mm_min": 0},
    "Z": {"max_velocity_mm_min": 1000, "max_acceleration_m_s2": 1, "max_jerk_m_s3": 5, "rapid_velocity_mm_min": 1000, "velocity_jump_mm_min": 0}}, )";
  const std::string a = R"({"name": "A", "carrier": "table", "direction": [1, 0, 0], "pivot_mm": [0, 0, 0],
    "max_velocity_deg_min": 3600, "rapid_velocity_deg_min": 3600, "max_acceleration_deg_s2": 100, "max_jerk_deg_s3": 1000,
    "min_deg": -90, "max_deg": 90})";
  const std::string c = R"({"name": "C", "carrier": "table", "direction": [0, 0, 1], "pivot_mm": [0, 0, 0],
    "max_velocity_deg_min": 3600, "rapid_velocity_deg_min": 3600, "max_acceleration_deg_s2": 100, "max_jerk_deg_s3": 1000,
    "continuous": true})";
  auto refused = [&](const std::string& tail, const std::string& words) {
    try {
      machineFromJson(head + tail + "}", "m.json");
      return std::string("accepted");
    } catch (const hsm::InputError& error) {
      const std::string message = error.what();
      return message.find(words) != std::string::npos ? std::string() : message;
    }
  };
  EXPECT_EQ(machineFromJson(head + "\"rotary_axes\": [" + a + ", " + c + "]}").rotaryAxes.size(), 2u);
  EXPECT_EQ(refused("\"rotary_axes\": [" + a + ", " + c + ", " + c + "]", "at most two"), "");
  EXPECT_EQ(refused("\"rotary_axes\": [" + a + ", " + a + "]", "named twice"), "");
  std::string twin = c;
  twin.replace(twin.find("\"C\""), 3, "\"A\"");
  EXPECT_EQ(refused("\"rotary_axes\": [" + c + ", " + twin + "]", "parallel"), "");
  EXPECT_EQ(refused("\"kinematics\": \"head-table\", \"rotary_axes\": [" + a + ", " + c + "]", "table-table"), "");
  std::string noTravel = a;
  noTravel.replace(noTravel.find("\"min_deg\""), 15, "\"x\": 0,");
  EXPECT_EQ(refused("\"rotary_axes\": [" + noTravel + "]", "\"min_deg\" and \"max_deg\""), "");
  std::string badCarrier = a;
  badCarrier.replace(badCarrier.find("table"), 5, "floor");
  EXPECT_EQ(refused("\"rotary_axes\": [" + badCarrier + "]", "\"carrier\""), "");
  std::string zero = a;
  zero.replace(zero.find("[1, 0, 0]"), 9, "[0, 0, 0]");
  EXPECT_EQ(refused("\"rotary_axes\": [" + zero + "]", "must not be zero"), "");
  std::string slow = a;
  slow.replace(slow.find("\"max_velocity_deg_min\": 3600"), 28, "\"max_velocity_deg_min\": -1");
  EXPECT_EQ(refused("\"rotary_axes\": [" + slow + "]", "max_velocity_deg_min"), "");
}
