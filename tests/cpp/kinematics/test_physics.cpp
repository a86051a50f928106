// The machine's physics (kinematics/physics.hpp) against the closed forms of DESIGN.md, with the Mikron's
// X axis (A 2.5 m/s², J 5 m/s³: A²/J = 1250 mm/s, 75 m/min).
#include "kinematics/physics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace hsm::kinematics;

namespace {
const Dynamics kSoft{2500.0, 5000.0, true};
const Dynamics kBrisk{2500.0, 5000.0, false};
}  // namespace

TEST(Physics, SpeedChangeTimeIsTheSCurveOrTheTrapezoid) {
  EXPECT_DOUBLE_EQ(speedChangeTime(100.0, kBrisk), 0.04);                        // Δv/A
  EXPECT_DOUBLE_EQ(speedChangeTime(100.0, kSoft), 2.0 * std::sqrt(0.02));        // Δv ≤ A²/J: A never reached
  EXPECT_DOUBLE_EQ(speedChangeTime(1250.0, kSoft), 2.0 * std::sqrt(0.25));       // the switch point, both forms
  EXPECT_DOUBLE_EQ(speedChangeTime(1250.0, kSoft), 1250.0 / 2500.0 + 2500.0 / 5000.0);
  EXPECT_DOUBLE_EQ(speedChangeTime(5000.0, kSoft), 2.0 + 0.5);                   // Δv/A + A/J
  EXPECT_EQ(speedChangeTime(0.0, kSoft), 0.0);
  EXPECT_EQ(speedChangeTime(-5.0, kBrisk), 0.0);
}

TEST(Physics, AStopAndAStartLoseOneChangeTime) {
  // Braking from v to 0 and starting back take 2t over v·t of path, which cruising covers in t.
  for (const Dynamics& d : {kSoft, kBrisk})
    for (double v : {10.0, 100.0, 2000.0}) EXPECT_DOUBLE_EQ(stopAndGoLoss(v, d), speedChangeTime(v, d));
  EXPECT_DOUBLE_EQ(stopAndGoLoss(500.0, Dynamics{1000.0, 1e6, true}), 0.5 + 0.001);
}

TEST(Physics, CurvatureSpeedTakesTheLowerOfAccelerationAndJerk) {
  EXPECT_DOUBLE_EQ(curvatureSpeed(10.0, kBrisk), std::sqrt(25000.0));            // √(A·R)
  // R = 10: √(A·R) = 158 mm/s, ∛(J·R²) = 79 mm/s: the jerk decides on small radii…
  EXPECT_DOUBLE_EQ(curvatureSpeed(10.0, kSoft), std::cbrt(5000.0 * 100.0));
  // …and the acceleration on large ones (R = 1000: √(A·R) = 1581 < ∛(J·R²) = 1710).
  EXPECT_DOUBLE_EQ(curvatureSpeed(1000.0, kSoft), std::sqrt(2500.0 * 1000.0));
}

TEST(Physics, PerAxisLimitsProjectOnADirection) {
  const Eigen::Vector3d limits(2500.0, 3000.0, 2000.0);
  EXPECT_DOUBLE_EQ(projectedLimit(limits, Eigen::Vector3d::UnitX()), 2500.0);
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1.0, 1.0, 0.0).normalized();
  EXPECT_DOUBLE_EQ(projectedLimit(limits, diagonal), 2500.0 * std::sqrt(2.0));   // X binds, at 1/cos 45°
  EXPECT_DOUBLE_EQ(projectedLimit(limits, Eigen::Vector3d(0.0, -0.6, 0.8)), std::min(3000.0 / 0.6, 2000.0 / 0.8));
  EXPECT_EQ(projectedLimit(limits, Eigen::Vector3d::Zero()), std::numeric_limits<double>::infinity());
}

TEST(Physics, ThePlanAxesAreTheSlowestOfXAndY) {
  MachineModel machine;
  machine.maxAcceleration = {2500.0, 3000.0, 500.0};  // Z slower still: not a plan axis
  machine.maxJerk = {6000.0, 5000.0, 100.0};
  const Dynamics plan = slowestPlanAxes(machine);
  EXPECT_EQ(plan.acceleration, 2500.0);
  EXPECT_EQ(plan.jerk, 5000.0);
  EXPECT_TRUE(plan.jerkLimited);  // an 840D in SOFT
  machine.jerkLimitedByDefault = false;
  EXPECT_FALSE(slowestPlanAxes(machine).jerkLimited);  // BRISK
  machine.jerkLimitedByDefault = true;
  for (ControllerKind trapezoidal : {ControllerKind::LinuxCNC, ControllerKind::Grbl}) {
    machine.controller = trapezoidal;
    EXPECT_FALSE(jerkLimitedByDefault(machine));
  }
}

TEST(Physics, CubeRootMatchesTheLibrary) {
  for (double x : {1e-300, 1e-12, 0.001, 0.5, 1.0, 2.0, 27.0, 3.3e7, 1e15, 1e300, -8.0, -1e-9})
    EXPECT_NEAR(cubeRoot(x), std::cbrt(x), 4e-16 * std::abs(std::cbrt(x))) << x;
  EXPECT_EQ(cubeRoot(0.0), 0.0);
  EXPECT_TRUE(std::isnan(cubeRoot(std::nan(""))));
  EXPECT_EQ(cubeRoot(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
}
