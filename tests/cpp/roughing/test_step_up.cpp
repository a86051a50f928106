// Intermediate levels inside the slices (step-up) on the wide slanted slot: Z-level roughing (S1 from the top
// face) meets walls leaning 30°, where one level per 8 mm slice leaves an 8 mm staircase.
#include "common/error.hpp"
#include "roughing/clearance.hpp"
#include "roughing/parts.hpp"
#include "roughing/removal.hpp"
#include "roughing/roughing.hpp"
#include "roughing/sweep.hpp"
#include "fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

using namespace hsm;
using namespace hsm::roughing;

namespace {
const fixtures::PartCase& slot() { return fixtures::wideSlot(); }

SweepResult sweepWith(double minimum, double scallop = 0.25) {
  SweepSettings s;
  s.stepUpMinimum = minimum;
  s.stepUpScallop = scallop;
  const fixtures::PartCase& c = slot();
  static const Partition z = partition(c.volume.solids.front(), c.shapes.part, Strategy::PlanesParallelToFace);
  return sweep(z, c.volume.solids.front(), c.shapes.part, c.shapes.stock, s);
}

RemovalResult removalOf(const SweepResult& r) {
  RemovalSettings s;
  s.resolution = 0.4;
  return simulateRemoval(r.moves, Cutter{}, slot().shapes.stock, slot().shapes.part, s);
}
}  // namespace

TEST(StepUp, IntermediateLevelsCutTheStaircaseOfLeaningWallsAndKeepTheAllowance) {
  const SweepResult plain = sweepWith(0.0), stepped = sweepWith(1.0);
  for (const Pass& p : plain.passes) EXPECT_FALSE(p.intermediate) << "no intermediate level without step-up";
  // The intermediate levels: between the main levels, open passes that start and end in what the main level
  // cleared, cut at their own heights (Z: S1's axis is the top face's normal).
  std::set<long> mainHeights, stepHeights;
  int open = 0;
  for (const Pass& p : stepped.passes) {
    const long h = std::lround(p.points.front().z() * 1000.0);
    (p.intermediate ? stepHeights : mainHeights).insert(h);
    open += !p.closed;
    for (const Eigen::Vector3d& q : p.points) EXPECT_NEAR(q.z() * 1000.0, double(h), 1e-6) << "a pass at one height";
  }
  EXPECT_GT(open, 0);
  EXPECT_GE(stepHeights.size(), 3u);
  for (long h : stepHeights) EXPECT_EQ(mainHeights.count(h), 0u) << "an intermediate level at a main level's height";
  // Never nearer the part than the allowance (the exact torus against the part's triangles), and a gain in
  // what is left beyond the allowance layer, paid in path.
  const Cutter cutter;
  const ClearanceReport clear = checkClearance(stepped.moves, slot().shapes.part, cutter, 0.49, 1.0);
  EXPECT_EQ(clear.tooClose, 0) << "closest " << clear.minimum << " mm at move " << clear.worstMove;
  const RemovalResult before = removalOf(plain), after = removalOf(stepped);
  EXPECT_LT(after.beyondAllowanceShare, 0.6 * before.beyondAllowanceShare)
      << before.beyondAllowanceShare << " % without step-up, " << after.beyondAllowanceShare << " % with it";
  EXPECT_LT(after.gougeVolume, 1e-6);
  EXPECT_TRUE(after.rapidFaults.empty() || after.rapidVolume < 1.0) << after.rapidVolume << " mm3 by rapids";
  EXPECT_GT(stepped.cuttingLength, plain.cuttingLength);
  // A finer scallop asks for at least as many levels.
  std::set<long> fine;
  for (const Pass& p : sweepWith(1.0, 0.05).passes)
    if (p.intermediate) fine.insert(std::lround(p.points.front().z() * 1000.0));
  EXPECT_GE(fine.size(), stepHeights.size());
}

TEST(StepUp, BadSettingsAreRefusedByName) {
  auto message = [](double minimum, double scallop) {
    try {
      sweepWith(minimum, scallop);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(0.05, 0.25).find("step-up minimum = 0.05 is outside [0.1, 100]"), std::string::npos);
  EXPECT_NE(message(0.1, 0.25).find("use a minimum of at least 0.125 mm"), std::string::npos);
  EXPECT_NE(message(1.0, 0.0).find("step-up scallop = 0 is outside"), std::string::npos);
  EXPECT_NE(message(1.0, std::nan("")).find("step-up scallop = nan"), std::string::npos);
  EXPECT_EQ(message(0.0, 0.25), "accepted");
}
