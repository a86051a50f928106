#include "common/error.hpp"
#include "kinematics/five_axis.hpp"
#include "kinematics/simulation.hpp"
#include "support/simulation.hpp"

#include "support/mutation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

using namespace hsm::kinematics;

namespace {
using hsm::test::preset;
using hsm::test::run;

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

namespace {
struct Pose5 {
  Eigen::Vector3d tip;
  double a, c, feed;
};

// Time-optimal lower bound on the joint-space path of a TCP program of lines with A and C (tests only): each
// block cut into 200 pieces by the test's own kinematics, each piece bounded by every axis's velocity and
// acceleration projected on it (no jerk, no curvature, no junction or cycle limit), trapezoidal profiles from a
// backward and a forward pass. A controller that keeps its axes within their limits takes at least this long.
double jointLowerBound(const std::vector<Pose5>& poses, const MachineModel& m) {
  struct Piece {
    double length, vmax, a;
  };
  std::vector<Piece> pieces;
  const int n = 200;
  Eigen::Matrix<double, 5, 1> vmax, amax;
  vmax << m.maxVelocity, m.rotaryAxes[0].maxVelocity, m.rotaryAxes[1].maxVelocity;
  amax << m.maxAcceleration, m.rotaryAxes[0].maxAcceleration, m.rotaryAxes[1].maxAcceleration;
  auto joints = [&](const Pose5& p0, const Pose5& p1, double t) {
    const Eigen::Vector3d tip = p0.tip + t * (p1.tip - p0.tip);
    const RotaryAngles angles{p0.a + t * (p1.a - p0.a), p0.c + t * (p1.c - p0.c)};
    Eigen::Matrix<double, 5, 1> q;
    q << linearAxesFor(m, tip, angles), angles[0], angles[1];
    return q;
  };
  for (size_t k = 1; k < poses.size(); ++k) {
    const double length = (poses[k].tip - poses[k - 1].tip).norm() / n;
    for (int i = 0; i < n; ++i) {
      const Eigen::Matrix<double, 5, 1> dq = joints(poses[k - 1], poses[k], double(i + 1) / n) -
                                             joints(poses[k - 1], poses[k], double(i) / n);
      double v = poses[k].feed, a = 1e300;
      for (int j = 0; j < 5; ++j)
        if (std::abs(dq[j]) > 1e-15) {
          v = std::min(v, vmax[j] * length / std::abs(dq[j]));
          a = std::min(a, amax[j] * length / std::abs(dq[j]));
        }
      pieces.push_back({length, v, a});
    }
  }
  std::vector<double> speed(pieces.size() + 1, 0.0);
  for (size_t i = 1; i < pieces.size(); ++i) speed[i] = std::min(pieces[i - 1].vmax, pieces[i].vmax);
  for (size_t i = pieces.size(); i-- > 0;)
    speed[i] = std::min(speed[i], std::sqrt(speed[i + 1] * speed[i + 1] + 2 * pieces[i].a * pieces[i].length));
  double total = 0.0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    speed[i + 1] = std::min(speed[i + 1], std::sqrt(speed[i] * speed[i] + 2 * pieces[i].a * pieces[i].length));
    total += blockProfile(pieces[i].length, speed[i], speed[i + 1], pieces[i].vmax, {pieces[i].a, 0, false}).time;
  }
  return total;
}
}  // namespace

TEST(FiveAxisSimulation, NeverBelowTheJointSpaceTimeOptimalBound) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> step(-4.0, 4.0), turn(-8.0, 8.0), feed(600, 12000);
  for (const char* name : {"mikron-ucp710-ac-840d", "linuxcnc-2.9-xyzac-trt"}) {
    const MachineModel m = preset(name);
    for (int program = 0; program < 20; ++program) {
      std::vector<Pose5> poses{{Eigen::Vector3d::Zero(), 0.0, 0.0, 0.0}};
      std::ostringstream text;
      text << std::fixed;
      text.precision(4);
      text << (m.controller == ControllerKind::Siemens840D ? "TRAORI\n" : "") << "G64\n";
      for (int k = 0; k < 60; ++k) {
        Pose5 p = poses.back();
        p.tip += Eigen::Vector3d(step(random), step(random), 0.2 * step(random));
        p.a = std::clamp(p.a + turn(random), -40.0, 40.0);
        p.c += turn(random);
        p.feed = feed(random) / 60.0;
        // Round as the text does, so that the bound and the simulation see the same path.
        for (int i = 0; i < 3; ++i) p.tip[i] = std::round(p.tip[i] * 1e4) / 1e4;
        p.a = std::round(p.a * 1e4) / 1e4;
        p.c = std::round(p.c * 1e4) / 1e4;
        text << "G1 X" << p.tip.x() << " Y" << p.tip.y() << " Z" << p.tip.z() << " A" << p.a << " C" << p.c << " F"
             << p.feed * 60.0 << "\n";
        poses.push_back(p);
      }
      const double simulated = run(text.str(), m).summary.totalTime, bound = jointLowerBound(poses, m);
      EXPECT_GE(simulated, bound * (1.0 - 1e-6)) << name << " program " << program;
      EXPECT_LT(simulated, 20.0 * bound) << name << " program " << program;  // and not absurdly slow
    }
  }
}

TEST(FiveAxisSimulation, FuzzedFiveAxisProgramsNeverCrash) {
  const std::string seed =
      "G21 G90\nTRAORI\nG0 X0 Y0 Z5 A10 C0\nG1 Z-1 F600\nG1 X10 A3=0.1 B3=0.2 C3=1\nG1 X20 C90 A-20\n"
      "ORIMKS\nG1 Y5 A3=0 B3=0.01 C3=1\nG93\nG1 X0 A5 F30\nG94\nG2 X10 Y5 I5 J0 C120 F900\nTRAFOOF\nG1 X1 C0\nM30\n";
  // The same program for the B/C machine: B where A turns.
  std::string seedBC = seed;
  for (const char* word : {" A10", " A-20", " A5"}) {
    const size_t at = seedBC.find(word);
    seedBC[at + 1] = 'B';
  }
  const std::string alphabet = "GXYZIJKFABC3=0123456789.-+ ()\n;TRAOIFWKSM%";
  const std::vector<std::string> names = {"mikron-ucp710-ac-840d", "swivel-head-bc-840d", "linuxcnc-2.9-xyzac-trt",
                                          "mikron-ucp710-840d"};
  std::vector<MachineModel> machines;
  for (const auto& name : names) machines.push_back(preset(name));
  std::mt19937 random(23);
  int simulated = 0, refused = 0;
  for (int round = 0; round < 20000; ++round) {
    const MachineModel& machine = machines[round % machines.size()];
    const std::string program =
        hsm::test::mutated(machine.kinematicsName() == "head-table" ? seedBC : seed, alphabet, random);
    try {
      const SimulationResult r = run(program, machine);
      ASSERT_TRUE(std::isfinite(r.summary.totalTime) && r.summary.totalTime >= 0.0) << program;
      for (const BlockResult& b : r.blocks) ASSERT_TRUE(b.rotaryEnd.allFinite() && b.machineEnd.allFinite()) << program;
      ++simulated;
    } catch (const hsm::InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(simulated, 1000);
  EXPECT_GT(refused, 1000);
}

TEST(FiveAxisSimulation, MachineAxesProgrammedMoveEveryAxisLinearly) {
  // LinuxCNC without TCP kinematics (trivkins with A and C joints): X Y Z are the machine's, all axes move
  // linearly, F is the speed of X Y Z; the tool tip on the workpiece is where the forward kinematics put it.
  MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  m.toolTipProgrammed = false;
  const SimulationResult r = run("G1 X10 Y0 Z0 A-30 C45 F1200\nG1 X20\n", m);
  ASSERT_EQ(r.blocks.size(), 2u);
  EXPECT_LT((r.blocks[1].machineEnd - Eigen::Vector3d(20, 0, 0)).norm(), 1e-12);
  const ToolPose pose = forwardKinematics(m, {{20, 0, 0}, {-30.0, 45.0}});
  EXPECT_LT((r.blocks[1].end - pose.tip).norm(), 1e-9);
  // The second block moves X alone: 10 mm at F1200 with LinuxCNC's trapezoid (X: 2500 mm/s²) from rest (the
  // rotary axes stop at the junction) to rest, at most with half of a on its ramps (LinuxCNC's last segment).
  const double v = 20.0, a = m.maxAcceleration.x();
  EXPECT_GE(r.blocks[1].time, 10.0 / v + v / a - 1e-9);
  EXPECT_LE(r.blocks[1].time, 10.0 / v + 2.0 * v / a + 1e-9);
}
