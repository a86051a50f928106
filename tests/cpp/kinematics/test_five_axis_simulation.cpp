#include "common/error.hpp"
#include "kinematics/five_axis.hpp"
#include "kinematics/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace hsm::kinematics;

namespace {
MachineModel preset(const std::string& name) { return loadMachine(name, {HSM_MACHINES_DIR}); }

SimulationResult run(const std::string& program, const MachineModel& machine) {
  std::istringstream stream(program);
  SimulationOptions options;
  options.keepBlocks = true;
  return simulate(stream, machine, {}, options);
}

double limitShare(const SimulationResult& r, SpeedLimit limit) {
  double total = 0.0;
  for (double t : r.summary.limitTime) total += t;
  return r.summary.limitTime[static_cast<int>(limit)] / total;
}

// Time to go from rest to v and back to rest over `distance`, cruising at v in between (v reachable).
double restToRest(double distance, double v, const Dynamics& d) {
  const double change = speedChangeTime(v, d);
  return 2.0 * change + (distance - v * change) / v;
}
}  // namespace

TEST(FiveAxisSimulation, TurningCAboutAFixedTipTakesWhatCAllows) {
  // TCP: the tip stays 50 mm off C's axis while C turns a full turn; X and Y run a circle, C is the slowest.
  const MachineModel m = preset("mikron-ucp710-ac-840d");
  const SimulationResult r = run("TRAORI\nG1 X50 Y0 Z0 F6000\nG1 C360 F100000\n", m);
  ASSERT_EQ(r.blocks.size(), 2u);
  const BlockResult& turn = r.blocks[1];
  const RotaryAxis& c = m.rotaryAxes[1];
  // X and Y move up to 50 mm·π/180 per degree of C: their jerk and acceleration bound C's too.
  const double rate = 50.0 * M_PI / 180.0;
  const Dynamics d{std::min({c.maxAcceleration, m.maxAcceleration.x() / rate, m.maxAcceleration.y() / rate}),
                   std::min({c.maxJerk, m.maxJerk.x() / rate, m.maxJerk.y() / rate}), true};
  const double expected = restToRest(360.0, c.maxVelocity, d);
  EXPECT_NEAR(turn.time, expected, 0.01 * expected) << "C: " << c.maxVelocity << " deg/s";
  EXPECT_EQ(turn.limit, SpeedLimit::C);
  EXPECT_NEAR(turn.length, 0.0, 1e-6);  // the tip did not move on the workpiece
  EXPECT_NEAR(turn.rotaryEnd[1], 360.0, 1e-9);
  EXPECT_LT((turn.machineEnd - Eigen::Vector3d(50, 0, 0)).norm(), 1e-6);  // back where it started, a turn later
  EXPECT_GT(limitShare(r, SpeedLimit::C), 0.5);
}

TEST(FiveAxisSimulation, FixedTiltedAxisCircleEqualsTheThreeAxisCircle) {
  // At fixed angles the table only moves the path: the same path programmed in machine axes on the 3-axis
  // machine takes the same time, as long as the rotary axes do not move.
  const MachineModel m = preset("mikron-ucp710-ac-840d");
  MachineModel three = m;
  three.rotaryAxes.clear();
  const RotaryAngles angles{30.0, 20.0};
  std::ostringstream tcp, machine;
  tcp << std::fixed;
  machine << std::fixed;
  tcp << "CYCLE832(0.01)\nTRAORI\nG0 A30 C20\nG1 X20 Y0 Z0 F4000\n";
  const Eigen::Vector3d first = linearAxesFor(m, {20, 0, 0}, angles);
  machine << "CYCLE832(0.01)\nG0 X" << first.x() << " Y" << first.y() << " Z" << first.z() << "\nG1 F4000\n";
  for (int k = 1; k <= 360; ++k) {
    const Eigen::Vector3d tip(20 * std::cos(k * M_PI / 180), 20 * std::sin(k * M_PI / 180), 0);
    const Eigen::Vector3d q = linearAxesFor(m, tip, angles);
    tcp << "G1 X" << tip.x() << " Y" << tip.y() << " Z0\n";
    machine << "G1 X" << q.x() << " Y" << q.y() << " Z" << q.z() << "\n";
  }
  const SimulationResult a = run(tcp.str(), m), b = run(machine.str(), three);
  double circleA = 0.0, circleB = 0.0;
  for (size_t k = a.blocks.size() - 360; k < a.blocks.size(); ++k) circleA += a.blocks[k].time;
  for (size_t k = b.blocks.size() - 360; k < b.blocks.size(); ++k) circleB += b.blocks[k].time;
  EXPECT_NEAR(circleA, circleB, 0.01 * circleB);
  EXPECT_GT(circleA, 0.0);
  // With C turning with the tip around the circle (A/C: the table turns under the tool), C limits.
  std::ostringstream turning;
  turning << std::fixed;
  turning << "TRAORI\nG0 A30 C0\nG1 X20 Y0 Z0 F4000\n";
  for (int k = 1; k <= 360; ++k)
    turning << "G1 X" << 20 * std::cos(k * M_PI / 180) << " Y" << 20 * std::sin(k * M_PI / 180) << " C" << 4 * k << "\n";
  const SimulationResult c = run(turning.str(), m);
  double circleC = 0.0;
  for (size_t k = c.blocks.size() - 360; k < c.blocks.size(); ++k) circleC += c.blocks[k].time;
  EXPECT_GT(circleC, 1.5 * circleA) << "C turns 1440° in the circle";
  EXPECT_GT(limitShare(c, SpeedLimit::C), 0.5);
}

TEST(FiveAxisSimulation, ALineThroughTheSingularitySwingsCAndSlowsTheTip) {
  // The tool axis sweeps across X, passing 0.56° from Z (A = 0) on the great circle of A3 B3 C3: the table must
  // turn C by 174° while the tip moves a few millimetres. (Exactly through Z, A would change sign instead.)
  const MachineModel m = preset("mikron-ucp710-ac-840d");
  const std::string start = "TRAORI\nG1 X-20 Y0 Z0 A3=-0.2 B3=0.01 C3=1 F4000\n";
  const SimulationResult through = run(start + "G1 X20 A3=0.2 B3=0.01 C3=1\n", m);
  const SimulationResult fixed = run(start + "G1 X20\n", m);
  ASSERT_EQ(through.blocks.size(), 2u);
  const BlockResult& line = through.blocks[1];
  const double swing = std::abs(line.rotaryEnd[1] - line.rotaryStart[1]);
  EXPECT_GT(swing, 170.0) << "C swings half a turn";
  EXPECT_LT(swing, 180.0);
  EXPECT_NEAR(line.length, 40.0, 1e-6);
  EXPECT_GT(line.time, 2.0 * fixed.blocks[1].time) << line.time << " s against " << fixed.blocks[1].time << " s";
  EXPECT_EQ(line.limit, SpeedLimit::C);
}

TEST(FiveAxisSimulation, InverseTimeFeed) {
  // G93 F60: the block lasts a second (and a little more, to accelerate and stop).
  const MachineModel m = preset("mikron-ucp710-ac-840d");
  const SimulationResult r = run("G93\nG1 X10 F60\nG94\nG1 X20 F600\n", m);
  ASSERT_EQ(r.blocks.size(), 2u);
  EXPECT_GT(r.blocks[0].time, 1.0);
  EXPECT_LT(r.blocks[0].time, 1.2);
  EXPECT_NEAR(r.blocks[0].programmedFeed, 10.0, 1e-9);  // mm/s
  EXPECT_THROW(run("G93\nG1 X10 F60\nG1 X20\n", m), ParseError);  // F on every G93 move
}

TEST(FiveAxisSimulation, ProgramsForAnotherMachineAreRefusedByName) {
  const MachineModel ac = preset("mikron-ucp710-ac-840d"), three = preset("mikron-ucp710-840d");
  auto message = [](const std::string& program, const MachineModel& m) {
    try {
      run(program, m);
    } catch (const hsm::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("G1 X1 B10 F100\n", ac).find("line 1: the program turns B but machine"), std::string::npos);
  EXPECT_NE(message("G1 X1 C10 F100\n", three).find("has no such axis"), std::string::npos);
  EXPECT_NE(message("TRAORI\nG1 X1 A3=1 C3=0 F100\n", three).find("has no rotary axes"), std::string::npos);
  EXPECT_NE(message("G1 X1 A3=0 B3=0 C3=0 F100\n", ac).find("line 1: orientation vector"), std::string::npos);
  EXPECT_NE(message("G1 X1 A3= F100\n", ac).find("line 1: A3= needs a number"), std::string::npos);
  EXPECT_NE(message("TRAORI\nG1 X1 A3=0 B3=0 C3=-1 F100\n", ac).find("line 2: machine"), std::string::npos)
      << "pointing up from under the table";
  // A program that names rotary axes only at 0 is a 3-axis program.
  EXPECT_EQ(message("G1 X1 A0 C0 F100\n", three), "accepted");
}

TEST(FiveAxisSimulation, LinuxCncTrtProgramsAreToolTipProgrammed) {
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  EXPECT_TRUE(m.toolTipProgrammed);
  const SimulationResult r = run("G1 X10 Y0 Z0 A-30 C45 F1200\nG1 X20\n", m);
  ASSERT_EQ(r.blocks.size(), 2u);
  const Eigen::Vector3d expected = linearAxesFor(m, {20, 0, 0}, {-30.0, 45.0});
  EXPECT_LT((r.blocks[1].machineEnd - expected).norm(), 1e-9);
  EXPECT_NEAR(r.blocks[1].length, 10.0, 1e-9);
}
