// LinuxCNC 2.9's planner in closed form. Blocks that turn rotary axes (RotaryPlanner::LinuxCnc): the program's
// coordinates with the axis limits, no blend and no look-ahead where a rotary axis turns, blocks from rest to
// rest overlapped by parabolic blends (G64) or stopping (G61). Chords shorter than a servo cycle at F: blend
// arcs that take them whole, each lasting a servo cycle; braking in time for a short block.
#include "common/error.hpp"
#include "kinematics/five_axis.hpp"
#include "kinematics/simulation.hpp"
#include "support/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

using namespace hsm::kinematics;

namespace {
using hsm::test::preset;
using hsm::test::run;

// n blocks of 1 mm along X, each turning C by 2 degrees, in the given path mode.
std::string chain(int n, const std::string& mode) {
  std::string program = mode + "\nF6000\n";
  for (int i = 1; i <= n; ++i)
    program += "G1 X" + std::to_string(i) + " C" + std::to_string(2 * i) + "\n";
  return program;
}
}  // namespace

TEST(LinuxCncRotary, PresetsSayHowTheyPlan) {
  EXPECT_EQ(preset("linuxcnc-2.9-xyzac-trt").rotaryPlanner, RotaryPlanner::LinuxCnc);
  EXPECT_EQ(preset("mikron-ucp710-ac-840d").rotaryPlanner, RotaryPlanner::JointSpace);
  EXPECT_EQ(preset("swivel-head-bc-840d").rotaryPlanner, RotaryPlanner::JointSpace);
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  EXPECT_EQ(machineFromJson(machineToJson(m)).rotaryPlanner, RotaryPlanner::LinuxCnc);
}

TEST(LinuxCncRotary, MachineFileRefusesAPlannerItsControllerLacks) {
  std::string text = machineToJson(preset("mikron-ucp710-ac-840d"));
  const std::string said = "\"planner\": \"joint-space\"";
  ASSERT_NE(text.find(said), std::string::npos);
  std::string wrong = text;
  wrong.replace(wrong.find(said), said.size(), "\"planner\": \"linuxcnc\"");
  try {
    machineFromJson(wrong, "m.json");
    FAIL() << "an 840D planned by LinuxCNC's rules was accepted";
  } catch (const hsm::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("joint-space"), std::string::npos) << error.what();
  }
  std::string unknown = text;
  unknown.replace(unknown.find(said), said.size(), "\"planner\": \"tcp\"");
  EXPECT_THROW(machineFromJson(unknown, "m.json"), hsm::InputError);
}

TEST(LinuxCncRotary, ChainOfRotaryBlocksOverlapsRestToRestProfiles) {
  // Each block: 1 mm of X with 2 degrees of C, so C's 300 deg/s² allows 150 mm/s² along it (X allows 2500);
  // G64 halves it (the parabolic end), the profile is a triangle of peak sqrt(a·L) (C's 30 deg/s allows
  // 15 mm/s), and each block starts as the one before it brakes: (n + 1)·sqrt(L / a) in all.
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  const int n = 20;
  const double a = 0.5 * m.rotaryAxes[1].maxAcceleration / 2.0;
  ASSERT_LT(std::sqrt(a), m.rotaryAxes[1].maxVelocity / 2.0);
  const SimulationResult blended = run(chain(n, "G64"), m);
  EXPECT_NEAR(blended.summary.totalTime, (n + 1) * std::sqrt(1.0 / a), 1e-6);
  // G61: full acceleration, each block stops before the next starts.
  const SimulationResult stopped = run(chain(n, "G61"), m);
  EXPECT_NEAR(stopped.summary.totalTime, n * 2.0 * std::sqrt(1.0 / (2.0 * a)), 1e-6);
  // Blocks and pieces: one per block, the block times adding up to the total.
  ASSERT_EQ(blended.blocks.size(), static_cast<size_t>(n));
  double sum = 0.0;
  for (const BlockResult& b : blended.blocks) sum += b.time;
  EXPECT_NEAR(sum, blended.summary.totalTime, 1e-9);
  // C alone, 2 degrees a block, under G64 P0.01: the blend's tolerance does not bind between turns of the
  // rotary axes alone (LinuxCNC gives them all the direction +X), so the chain overlaps the same way.
  std::string turns = "G64 P0.01\nF60000\n";
  for (int i = 1; i <= n; ++i) turns += "G1 C" + std::to_string(2 * i) + "\n";
  const double c = 0.5 * m.rotaryAxes[1].maxAcceleration;
  EXPECT_NEAR(run(turns, m).summary.totalTime, (n + 1) * std::sqrt(2.0 / c), 1e-6);
  // The joint-space planner looks ahead through the same chain: far faster than LinuxCNC.
  MachineModel joint = m;
  joint.rotaryPlanner = RotaryPlanner::JointSpace;
  EXPECT_LT(run(chain(n, "G64"), joint).summary.totalTime, 0.7 * blended.summary.totalTime);
}

TEST(LinuxCncRotary, JointLimitsDoNotBindCoordinatedMotion) {
  // C turns 90 degrees about a tip 1 m off its axis: X and Y would run at 17 mm per degree, far beyond their
  // limits at C's 30 deg/s, but LinuxCNC plans A B C and the tip with the [AXIS_*] limits only.
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  const std::string program = "G64\nG1 X1000 F12000\nG1 C90 F100000\n";
  const SimulationResult r = run(program, m);
  ASSERT_EQ(r.blocks.size(), 2u);
  const RotaryAxis& c = m.rotaryAxes[1];
  const double a = 0.5 * c.maxAcceleration;  // the program's last block ends parabolic: half
  EXPECT_NEAR(r.blocks[1].time, 90.0 / c.maxVelocity + c.maxVelocity / a, 1e-6);
  EXPECT_EQ(r.blocks[1].limit, SpeedLimit::C);
  MachineModel joint = m;
  joint.rotaryPlanner = RotaryPlanner::JointSpace;
  EXPECT_GT(run(program, joint).blocks[1].time, 2.0 * r.blocks[1].time);
}

TEST(LinuxCncRotary, BlocksThatTurnNoAxisArePlannedAsThreeAxisBlocks) {
  // A tilted square: once A is set, the sides are the 3-axis LinuxCNC model's (blend arcs at the corners),
  // side for side the same times as the square on the 3-axis preset of the same linear limits.
  const MachineModel m = preset("linuxcnc-2.9-xyzac-trt");
  const std::string square = "G1 X50\nG1 Y50\nG1 X0\nG1 Y0\nG1 X50\n";
  const SimulationResult tilted = run("G64\nG1 Z1 A20 F3000\n" + square, m);
  const SimulationResult flat = run("G64\nG1 Z1 F3000\n" + square, preset("linuxcnc-2.9"));
  ASSERT_EQ(tilted.blocks.size(), 6u);
  ASSERT_EQ(flat.blocks.size(), 6u);
  for (size_t k : {2u, 3u, 4u}) EXPECT_NEAR(tilted.blocks[k].time, flat.blocks[k].time, 1e-9) << "side " << k;
  // Their angles are where the program left them, and the machine's X Y Z where the tilted table puts the tip.
  const BlockResult& side = tilted.blocks[3];
  EXPECT_NEAR(side.rotaryEnd[0], 20.0, 1e-12);
  EXPECT_LT((side.machineEnd - linearAxesFor(m, side.end, {20.0, 0.0})).norm(), 1e-9);
}

TEST(LinuxCncChords, ChordsShorterThanAServoCycleAtFBecomeBlendArcs) {
  // A circle of R 5 as 0.05 mm chords at F6000 under G64 P0.01 Q0: each chord would need 0.5 ms at F, and each
  // junction turns 0.01 rad, a kink above a tenth of the axis limits in a cycle. LinuxCNC rounds every junction
  // with a blend arc as long as half of each chord, so the arcs take the chords whole, and each arc lasts 1.02
  // servo cycles (TP_MIN_SEGMENT_CYCLES): 0.05 mm / 1.02 ms, about 2941 mm/min, all the way round.
  const MachineModel m = preset("linuxcnc-2.9");
  const int chords = 628;
  const double radius = 5.0, step = 2.0 * M_PI / chords;
  std::ostringstream program;
  program << std::fixed;
  program.precision(6);
  program << "G64 P0.01 Q0\nG1 X" << radius << " Y0 F6000\n";
  for (int i = 1; i <= chords; ++i)
    program << "G1 X" << radius * std::cos(i * step) << " Y" << radius * std::sin(i * step) << "\n";
  const SimulationResult r = run(program.str(), m);
  const double chord = 2.0 * radius * std::sin(0.5 * step);
  const double expected = chord / (1.02 * m.interpolationCycle) * 60.0;
  int checked = 0;
  for (size_t k = chords / 4; k < 3 * chords / 4; ++k) {
    EXPECT_NEAR(r.blocks[k].meanFeed * 60.0, expected, 0.01 * expected) << "chord " << k;
    // Each block reports its programmed end, not the end of the blend arc that rounds it.
    const Eigen::Vector3d end(radius * std::cos(k * step), radius * std::sin(k * step), 0.0);
    EXPECT_LT((r.blocks[k].end - end).norm(), 1e-6) << "chord " << k;
    ++checked;
  }
  EXPECT_EQ(checked, chords / 2);
}

TEST(LinuxCncChords, BrakesInTimeForAShortBlockBehindALongOne) {
  // 10 mm, then 0.01 mm (one servo cycle at most 10 mm/s), then 10 mm along X at F6000: the machine brakes
  // from 100 to 10 mm/s at X's 2500 mm/s² before the short block, and the last block (parabolic end) runs at
  // half of it. The short block was too short to stop in when it arrived: its junction must still bind.
  const MachineModel m = preset("linuxcnc-2.9");
  const SimulationResult r = run("G64\nF6000\nG1 X10\nG1 X10.01\nG1 X20.01\n", m);
  ASSERT_EQ(r.blocks.size(), 3u);
  const double a = m.maxAcceleration.x(), v = 100.0, slow = 10.0;
  const double first = v / a + (10.0 - v * v / (2 * a) - (v * v - slow * slow) / (2 * a)) / v + (v - slow) / a;
  const double h = 0.5 * a;
  const double last = (v - slow) / h + v / h + (10.0 - (v * v - slow * slow) / (2 * h) - v * v / (2 * h)) / v;
  EXPECT_NEAR(r.blocks[0].exitFeed, slow, 1e-9);
  EXPECT_NEAR(r.blocks[0].time, first, 1e-9);
  EXPECT_NEAR(r.blocks[1].time, 0.01 / slow, 1e-9);
  EXPECT_NEAR(r.blocks[2].time, last, 1e-9);
}

TEST(LinuxCncChords, ARapidAndAFeedMoveAreNeverBlended) {
  // G0 X10 then G1 X20 in a straight line under G64: LinuxCNC stops between them (tp.c handleModeChange), the
  // rapid at its full 2500 mm/s² (a triangle: 10 mm never reach 200 mm/s), the feed move as the program's last
  // (half of it, to F6000 and back).
  const MachineModel m = preset("linuxcnc-2.9");
  const SimulationResult r = run("G64\nG0 X10\nG1 X20 F6000\n", m);
  ASSERT_EQ(r.blocks.size(), 2u);
  const double a = m.maxAcceleration.x(), h = 0.5 * a, v = 100.0;
  EXPECT_NEAR(r.blocks[0].exitFeed, 0.0, 1e-12);
  EXPECT_NEAR(r.blocks[0].time, 2.0 * std::sqrt(10.0 / a), 1e-9);
  EXPECT_NEAR(r.blocks[1].time, 2.0 * v / h + (10.0 - v * v / h) / v, 1e-9);
}
