#include "kinematics/moves.hpp"
#include "kinematics/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>

using namespace hsm::kinematics;

namespace {
MachineModel preset(const std::string& name) { return loadMachine(name, {HSM_MACHINES_DIR}); }

SimulationResult run(const std::string& program, const MachineModel& machine, bool keep = true) {
  std::istringstream stream(program);
  SimulationOptions options;
  options.keepBlocks = keep;
  return simulate(stream, machine, {}, options);
}

std::string repeat(const std::string& line, int times) {
  std::string text;
  for (int i = 0; i < times; ++i) text += line;
  return text;
}

// Time-optimal lower bound on the same path (tests only): trapezoidal profiles with the full axis
// acceleration projected on lines (the largest in-plane axis on arcs), no jerk limit, no look-ahead limit,
// no cycle limit, every junction as fast as both blocks allow except exact stops. Any controller that
// keeps its axes within their velocity and acceleration limits takes at least this long.
double lowerBound(const std::vector<Block>& blocks, const MachineModel& m) {
  struct Piece {
    double length, vmax, junction, a;
  };
  std::vector<Piece> pieces;
  for (size_t k = 0; k < blocks.size(); ++k) {
    const Block& b = blocks[k];
    const double length = b.length();
    if (length <= 0) continue;
    const Eigen::Vector3d u = b.tangent(false);
    double a = 1e300, v = 1e300;
    if (b.isArc()) {
      a = m.maxAcceleration.maxCoeff();
      v = m.maxVelocity.maxCoeff();
      v = std::min(v, std::sqrt(a * b.radius));
    } else {
      for (int i = 0; i < 3; ++i)
        if (std::abs(u[i]) > 1e-12) {
          a = std::min(a, m.maxAcceleration[i] / std::abs(u[i]));
          v = std::min(v, (b.motion == Motion::Rapid ? m.rapidVelocity[i] : m.maxVelocity[i]) / std::abs(u[i]));
        }
    }
    if (b.motion != Motion::Rapid) v = std::min(v, b.feed);
    const bool stop = pieces.empty() || (k > 0 && blocks[k - 1].pathMode == PathMode::ExactStop &&
                                         m.controller != ControllerKind::Grbl);
    const double junction = stop ? 0.0 : std::min(v, pieces.back().vmax);
    pieces.push_back({length, v, junction, a});
  }
  const size_t n = pieces.size();
  std::vector<double> entry(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) entry[i] = pieces[i].junction;
  for (size_t i = n; i-- > 0;)  // backward
    entry[i] = std::min(entry[i], std::sqrt(entry[i + 1] * entry[i + 1] + 2 * pieces[i].a * pieces[i].length));
  double total = 0.0;
  for (size_t i = 0; i < n; ++i) {  // forward, and the time of each trapezoid
    entry[i + 1] = std::min(entry[i + 1], std::sqrt(entry[i] * entry[i] + 2 * pieces[i].a * pieces[i].length));
    total += blockProfile(pieces[i].length, entry[i], entry[i + 1], pieces[i].vmax, {pieces[i].a, 0, false}).time;
  }
  return total;
}

std::string randomProgram(std::mt19937& random, int blocks) {
  std::uniform_real_distribution<double> step(-3.0, 3.0), longStep(-60.0, 60.0), feed(300, 9000);
  std::ostringstream text;
  text.precision(4);
  text << std::fixed << "G17 G90\nG0 X0 Y0 Z0\n";
  const char* modes[] = {"G64", "G61", "G642", "G64 P0.01", "CYCLE832(0.02)", "BRISK", "SOFT"};
  double x = 0, y = 0;
  for (int i = 0; i < blocks; ++i) {
    const int kind = random() % 10;
    if (kind == 0) text << modes[random() % 7] << "\n";
    const double dx = (random() % 5 == 0) ? longStep(random) : step(random);
    const double dy = (random() % 5 == 0) ? longStep(random) : step(random);
    if (kind == 1) {
      const double r = 2.0 + std::abs(step(random)) * 3;
      text << (random() % 2 ? "G2" : "G3") << " X" << x + dx << " Y" << y + dy << " R" << std::max(r, std::hypot(dx, dy))
           << " F" << feed(random) << "\n";
    } else if (kind == 2) {
      text << "G0 X" << x + dx << " Y" << y + dy << " Z" << step(random) << "\n";
    } else {
      text << "G1 X" << x + dx << " Y" << y + dy << " Z" << 0.1 * step(random) << " F" << feed(random) << "\n";
    }
    x += dx;
    y += dy;
  }
  return text.str();
}
}  // namespace

TEST(Simulation, LongLineRestToRestJerkAndAccelerationLimited) {
  MachineModel m = preset("mikron-ucp710-840d");
  const double v = 100.0;  // F6000
  const SimulationResult soft = run("G0 X0 Y0 Z0\nSOFT G1 X200 F6000\n", m);
  EXPECT_NEAR(soft.summary.cuttingTime, 200.0 / v + 2.0 * std::sqrt(v / 5000.0), 1e-9);
  const SimulationResult brisk = run("G0 X0 Y0 Z0\nBRISK G1 X200 F6000\n", m);
  EXPECT_NEAR(brisk.summary.cuttingTime, 200.0 / v + v / 2500.0, 1e-9);
  EXPECT_NEAR(brisk.summary.naiveCuttingTime, 2.0, 1e-12);
}

TEST(Simulation, SteadySpeedOnACircleAsArcs) {
  MachineModel m = preset("mikron-ucp710-840d");
  for (double radius : {2.0, 20.0, 200.0}) {
    for (const char* mode : {"SOFT", "BRISK"}) {
      std::ostringstream program;
      program << "G0 X" << radius << " Y0\nG64 " << mode << "\n" << repeat("G2 I" + std::to_string(-radius) + " F6000\n", 6);
      const SimulationResult r = run(program.str(), m);
      const double a = 2500.0, j = 5000.0;  // the weaker in-plane axis (X)
      double expected = std::min(100.0, std::sqrt(a * radius));
      if (std::string(mode) == "SOFT") expected = std::min(expected, std::cbrt(j * radius * radius));
      const BlockResult& middle = r.blocks[3];
      EXPECT_NEAR(middle.meanFeed, expected, 1e-6 * expected) << "R " << radius << " " << mode;
      EXPECT_NEAR(middle.minFeed, expected, 1e-6 * expected);
    }
  }
}

TEST(Simulation, SteadySpeedOnACircleAsFineChords) {
  MachineModel m = preset("mikron-ucp710-840d");
  m.interpolationCycle = 0.0;  // the block-processing limit is tested on its own below
  const double radius = 20.0;
  std::ostringstream program;
  program.precision(6);
  program << std::fixed << "G0 X" << radius << " Y0\nG64 SOFT\nG1 F6000\n";
  const int chords = 720;
  for (int i = 1; i <= 3 * chords; ++i)
    program << "X" << radius * std::cos(2 * M_PI * i / chords) << " Y" << radius * std::sin(2 * M_PI * i / chords) << "\n";
  const SimulationResult r = run(program.str(), m);
  const double expected = std::min({100.0, std::sqrt(2500.0 * radius), std::cbrt(5000.0 * radius * radius)});
  const BlockResult& middle = r.blocks[r.blocks.size() / 2];
  EXPECT_NEAR(middle.meanFeed, expected, 0.002 * expected);  // the chords' circumradius is the circle's
}

TEST(Simulation, AccelerationSpansChainsOfShortBlocks) {
  // 100 mm as one block or as 1000 collinear blocks of 0.1 mm: the S-curves run across the blocks, so the
  // times agree (a zero-acceleration S-curve per block would take many times longer).
  MachineModel m = preset("mikron-ucp710-840d");
  m.interpolationCycle = 0.0;
  m.lookAheadBlocks = 1000;
  for (const char* mode : {"SOFT", "BRISK"}) {
    const double one = run(std::string(mode) + " G1 X100 F6000\n", m, false).summary.totalTime;
    const double many = run(std::string(mode) + " G1 F6000\n" + repeat("G91 X0.1\n", 1000), m, false).summary.totalTime;
    EXPECT_NEAR(many, one, 0.01 * one) << mode;
  }
}

TEST(Simulation, ShortBlocksAreLimitedByTheInterpolationCycle) {
  const MachineModel m = preset("mikron-ucp710-840d");  // 4 ms per block at least
  const SimulationResult r = run("G0 X0 Y0\nG1 F6000\n" + repeat("G91 X0.1\n", 2000), m);
  EXPECT_NEAR(r.blocks[1000].meanFeed, 0.1 / 0.004, 1e-9);  // 25 mm/s, not 100
  EXPECT_EQ(r.summary.feedClasses.blocks[0], 1.0);           // every block below 0.3 of the programmed feed
}

TEST(Simulation, NeverFasterThanTheTimeOptimalBound) {
  std::mt19937 random(5);
  for (const char* name : {"mikron-ucp710-840d", "linuxcnc-2.9", "grbl"}) {
    const MachineModel m = preset(name);
    for (int round = 0; round < 20; ++round) {
      const std::string program = randomProgram(random, 300);
      const std::vector<Block> blocks = readProgram(program);
      const SimulationResult r = simulateBlocks(blocks, m);
      const double bound = lowerBound(blocks, m);
      EXPECT_GE(r.summary.totalTime, bound * (1 - 1e-9)) << name << " round " << round;
      EXPECT_LE(r.summary.totalTime, 50 * bound) << name;  // and not absurdly slow
    }
  }
}

TEST(Simulation, PerBlockTimesAddUpToTheTotal) {
  std::mt19937 random(9);
  const std::string program = randomProgram(random, 1000) + "G4 P2\n";
  for (const char* name : {"mikron-ucp710-840d", "linuxcnc-2.9", "grbl"}) {
    const SimulationResult r = run(program, preset(name));
    double sum = 0.0, lastEnd = 0.0;
    for (const BlockResult& b : r.blocks) {
      EXPECT_NEAR(b.startTime, lastEnd, 1e-9);
      EXPECT_LE(b.minFeed, b.meanFeed * (1 + 1e-9));
      EXPECT_LE(b.meanFeed, b.programmedFeed * (1 + 1e-9));
      sum += b.time;
      lastEnd = b.startTime + b.time;
    }
    EXPECT_NEAR(sum + r.summary.dwellTime, r.summary.totalTime, 1e-9 * r.summary.totalTime) << name;
    EXPECT_DOUBLE_EQ(r.summary.dwellTime, 2.0);
    EXPECT_EQ(static_cast<long>(r.blocks.size()), r.summary.blockCount);
    EXPECT_NEAR(r.summary.cuttingTime + r.summary.rapidTime + r.summary.dwellTime, r.summary.totalTime, 1e-9);
    double shares = 0.0;
    for (double s : r.summary.feedClasses.time) shares += s;
    EXPECT_NEAR(shares, 1.0, 1e-12);
  }
}

TEST(Simulation, LinuxCnc29Behaviour) {
  const MachineModel m = preset("linuxcnc-2.9");  // X acceleration 2500 mm/s²
  EXPECT_NEAR(run("G61 G1 X100 F6000\n", m).summary.totalTime, 1.04, 1e-9);
  EXPECT_NEAR(run("G64 G1 X100 F6000\n", m).summary.totalTime, 1.08, 1e-9);
  const SimulationResult circle = run("G0 X2 Y0\nG64\n" + repeat("G2 I-2 F6000\n", 5), m);
  EXPECT_NEAR(circle.blocks[3].meanFeed * 60.0, 3948.0, 1.0);  // sqrt(0.866 · 2500 · 2) mm/s in mm/min
}

TEST(Simulation, GrblJunctionDeviation) {
  const MachineModel m = preset("grbl");  // a = 500 mm/s², δ = 0.01 mm
  const SimulationResult r = run("G1 X50 F3000\nY50\n", m);
  const double theta = M_PI / 2;  // grbl's angle between the reversed entry and the exit
  const double expected = std::sqrt(500.0 * 0.01 * std::sin(theta / 2) / (1 - std::sin(theta / 2)));
  EXPECT_NEAR(r.blocks[0].exitFeed, expected, 1e-9);
}

TEST(Simulation, ShorterLookAheadIsSlower) {
  MachineModel deep = preset("mikron-ucp710-840d"), shallow = deep;
  shallow.lookAheadBlocks = 5;
  deep.interpolationCycle = shallow.interpolationCycle = 0.0;
  const std::string program = "G0 X0 Y0\nCYCLE832(0.01)\nG1 F6000\n" + repeat("G91 X0.05\n", 4000);
  const double slow = run(program, shallow, false).summary.totalTime;
  const double fast = run(program, deep, false).summary.totalTime;
  EXPECT_GT(slow, 1.5 * fast);  // 5 blocks of 0.05 mm are too short to reach 6 m/min and still stop
}

TEST(Simulation, SummaryOnlyKeepsNoBlocksAndTraceFollowsTheProfile) {
  const MachineModel m = preset("mikron-ucp710-840d");
  std::istringstream stream("G1 X100 F6000\nY50\n");
  SimulationOptions options;
  options.tracePeriod = 0.001;
  const SimulationResult r = simulate(stream, m, {}, options);
  EXPECT_TRUE(r.blocks.empty());
  ASSERT_GT(r.trace.size(), 1000u);
  EXPECT_NEAR(r.trace.size() * 0.001, r.summary.totalTime, 0.0011);
  for (size_t i = 1; i < r.trace.size(); ++i) {
    const auto &a = r.trace[i - 1], &b = r.trace[i];
    const double moved = std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
    EXPECT_LE(moved, 0.001 * std::max(a.v, b.v) + 1e-6);  // positions consistent with the speeds
    EXPECT_LE(b.v, 100.0 + 1e-9);
  }
}

TEST(Machine, PresetsLoadAndBadFilesAreRefusedByKey) {
  const std::vector<std::string> names = machineNames({HSM_MACHINES_DIR});
  for (const std::string& name : names) EXPECT_NO_THROW(preset(name)) << name;
  // Every machine file is listed (presets may be added), and the ones the examples and docs name are there.
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(HSM_MACHINES_DIR))
    files += entry.path().extension() == ".json";
  EXPECT_EQ(names.size(), files);
  for (const char* needed : {"mikron-ucp710-840d", "linuxcnc-2.9", "grbl", "fanuc-31i-b5-vmc", "haas-vf2", "haas-umc750"})
    EXPECT_NE(std::find(names.begin(), names.end(), needed), names.end()) << needed;
  const MachineModel m = preset("mikron-ucp710-840d");
  EXPECT_DOUBLE_EQ(m.maxAcceleration.y(), 3000.0);
  EXPECT_DOUBLE_EQ(m.maxVelocity.x(), 500.0);
  EXPECT_EQ(machineFromJson(machineToJson(m)).maxJerk, m.maxJerk);
  try {
    preset("fanuc");
    FAIL();
  } catch (const hsm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("use one of fanuc-31i-b5-vmc, grbl, haas-umc750, "), std::string::npos) << e.what();
  }
  std::string text = machineToJson(m);
  text.replace(text.find("\"max_jerk_m_s3\""), 15, "\"max_jerk\"");
  try {
    machineFromJson(text, "my.json");
    FAIL();
  } catch (const hsm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("my.json axis X: missing \"max_jerk_m_s3\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(machineFromJson("{nope", "x.json"), hsm::InputError);
}

TEST(Simulation, MovesRunAsTheBlocksOfTheirGcode) {
  MoveArray moves(5, 4);
  moves << 0, 0, 5, 1,   // G0 above the start
      0, 0, 0, 0,        // G1 down
      40, 0, 0, 0, 40, 0, 0, 0,  // the same point twice: the second moves nothing
      40, 10, 0, 0;
  const std::vector<Block> blocks = movesToBlocks(moves, 100.0);
  ASSERT_EQ(blocks.size(), 4u);
  EXPECT_EQ(blocks[0].motion, Motion::Rapid);
  EXPECT_EQ(blocks[0].feed, 0.0);
  EXPECT_EQ(blocks[3].line, 5);  // rows counted from 1, the skipped one included
  const MachineModel mikron = preset("mikron-ucp710-840d");
  const auto text = run("G0 X0 Y0 Z5\nG1 Z0 F6000\nG1 X40\nG1 X40\nG1 Y10\n", mikron, false).summary;
  const auto direct = simulateBlocks(blocks, mikron).summary;
  EXPECT_NEAR(direct.totalTime, text.totalTime, 1e-12);
  EXPECT_EQ(direct.blockCount, text.blockCount);
  MoveArray bad = moves;
  bad(2, 1) = std::nan("");
  EXPECT_THROW(movesToBlocks(bad, 100.0), hsm::InputError);
  EXPECT_THROW(movesToBlocks(moves, 0.0), hsm::InputError);
  bad(2, 1) = 2e9;
  EXPECT_THROW(movesToBlocks(bad, 100.0), hsm::InputError);
}

// LinuxCNC 2.9 against closed forms derived from its planner (and checked with the LinuxCNC oracle,
// docs/oracle.md): X/Y a = 2500 mm/s², servo cycle 1 ms.
TEST(LinuxCnc, NaiveCamMergesCollinearChordsWithinQ) {
  const MachineModel m = preset("linuxcnc-2.9");
  std::string chords;
  for (int i = 1; i <= 1000; ++i) chords += "X" + std::to_string(0.05 * i) + "\n";
  // Merged: lines of 101 chords (5.05 mm), cruising at F; the last one brakes at a/2 (its parabolic end):
  // 50/100 + 100/(2·2500) + 100/(2·1250) = 0.56 s.
  const auto merged = run("G64 P0.01\nG1 F6000\n" + chords, m, false).summary;
  EXPECT_NEAR(merged.totalTime, 0.56, 1e-6);
  EXPECT_EQ(merged.blockCount, 10);
  // Q0: every 0.05 mm chord lasts a servo cycle at least: 50 mm/s, twice as long.
  const auto single = run("G64 P0.01 Q0\nG1 F6000\n" + chords, m, false).summary;
  EXPECT_EQ(single.blockCount, 1000);
  EXPECT_GT(single.totalTime, 1.0);
  // A zigzag 0.02 mm off the line stays unmerged within Q 0.01, and merges within Q 0.03.
  std::string zigzag;
  for (int i = 1; i <= 100; ++i) zigzag += "X" + std::to_string(0.5 * i) + (i % 2 ? " Y0.02\n" : " Y0\n");
  EXPECT_EQ(run("G64 P0.01\nG1 F6000\n" + zigzag, m, false).summary.blockCount, 100);
  EXPECT_LT(run("G64 P0.03\nG1 F6000\n" + zigzag, m, false).summary.blockCount, 5);
}

TEST(LinuxCnc, BlendArcsTakeTheCornerAndLinesTheFullAcceleration) {
  const MachineModel m = preset("linuxcnc-2.9");
  // G64 square of 50 mm: blend arcs planned for F (R = max(v²/(0.866·a), the parabolic-equivalent blend:
  // 8 mm over φ = π/2) = 5.09 mm), 2.18 mm shorter per corner; full a to start, a/2 at the end:
  // 193.45/100 + 0.02 + 0.04 = 1.9945 s (LinuxCNC measured 1.994 s).
  const std::string square = "G1 F6000 X50\nY50\nX0\nY0\n";
  EXPECT_NEAR(run("G64\n" + square, m, false).summary.totalTime, 1.9945, 2e-4);
  // G61: rest to rest on each side at 0.9·a (each corner is a kink), and a servo cycle at rest per stop:
  // 4 × (0.5 + 100/2250) + 3 × 0.001 = 2.1808 s (LinuxCNC 2.179 s).
  EXPECT_NEAR(run("G61\n" + square, m, false).summary.totalTime, 4 * (0.5 + 100.0 / 2250.0) + 0.003, 1e-9);
}

TEST(LinuxCnc, ALongSideSlowsOnlyNearTheCornerItBlends) {
  const MachineModel m = preset("linuxcnc-2.9");
  // G64 without P: a 60 mm side turning 135° into a 2.83 mm step-over. The blend is held to a quarter of the
  // shorter block (0.707 mm: R = 0.439 mm, sqrt(0.866·2500·0.439) = 30.8 mm/s), and only near the corner.
  const auto r = run("G64\nG1 F6000 X60\nX58 Y2\nX0\n", m);
  ASSERT_GE(r.blocks.size(), 3u);
  EXPECT_NEAR(r.blocks[0].exitFeed, std::sqrt(0.866 * 2500.0 * 0.707 * std::cos(M_PI * 67.5 / 180) /
                                              (1 - std::cos(M_PI * 67.5 / 180))), 0.05);
  EXPECT_GT(r.blocks[0].meanFeed, 0.85 * 100.0);  // it cruises at F until it brakes (capped by the blend: 31)
}

TEST(LinuxCnc, AChordedCircleRunsAtOneSpeedInEveryDirection) {
  const MachineModel m = preset("linuxcnc-2.9");
  std::string circle = "G0 X20 Y0\nG64\nG1 F6000\n";
  for (int i = 1; i <= 720; ++i)
    circle += "X" + std::to_string(20 * std::cos(i * M_PI / 360)) + " Y" + std::to_string(20 * std::sin(i * M_PI / 360)) + "\n";
  const auto r = run(circle, m);
  double low = 1e9, high = 0.0;
  for (size_t i = 100; i + 100 < r.blocks.size(); ++i) {
    low = std::min(low, r.blocks[i].meanFeed);
    high = std::max(high, r.blocks[i].meanFeed);
  }
  EXPECT_LT(high / low, 1.01) << low * 60 << " to " << high * 60 << " mm/min";
}
