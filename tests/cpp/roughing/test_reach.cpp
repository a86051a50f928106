// The split of what a roughing leaves (reach.hpp), on the slanted slot: along Z (S1) the overhanging wall
// hides a wedge no straight tool reaches, along the slot's own axis (S3) only the allowance layer is out of
// reach; a path's step-up levels take what lay between its main levels.
#include "common/error.hpp"
#include "roughing/parts.hpp"
#include "roughing/reach.hpp"
#include "roughing/roughing.hpp"
#include "roughing/sweep.hpp"
#include "fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace hsm;
using namespace hsm::roughing;

namespace {
const fixtures::PartCase& slot() { return fixtures::plainSlot(); }

LeftSplit splitOf(Strategy strategy, double stepUp) {
  const fixtures::PartCase& c = slot();
  const RemovalSolid& solid = c.volume.solids.front();
  const Partition p = partition(solid, c.shapes.part, strategy);
  SweepSettings s;
  s.stepUpMinimum = stepUp;
  const SweepResult r = sweep(p, solid, c.shapes.part, c.shapes.stock, s);
  return splitWhatIsLeft(p, solid, c.shapes.part, s.cutter, s.allowance, r.moves, 0.25);
}
}  // namespace

TEST(Reach, WhatNoToolAlongTheAxisReachesAndWhatLiesBetweenLevels) {
  const double volume = slot().volume.volume;  // 15,360 mm³
  const LeftSplit z = splitOf(Strategy::PlanesParallelToFace, 0.0);
  EXPECT_NEAR(z.volume, volume, 0.01 * volume) << "the solid's material, sampled";
  // Along Z the wall leaning over the slot hides a wedge: 27.6 % of the slot from a line (closed form 28.2 %),
  // more for a tool that keeps its radius and the allowance from the wall.
  EXPECT_GT(z.unreachable / volume, 0.28);
  EXPECT_LT(z.unreachable / volume, 0.50);
  EXPECT_GT(z.betweenLevels / volume, 0.02) << "8 mm levels on a leaning wall leave a staircase";
  EXPECT_GE(z.levels, 2);
  // Along the slot's axis only the allowance layer on the walls and floor is out of reach (0.5 mm on
  // 16 + 2 × 24 mm of section over 40 mm: 8.3 %, less where the stock's top cuts the walls).
  const LeftSplit axis = splitOf(Strategy::SetupPlanes, 0.0);
  EXPECT_LT(axis.unreachable / volume, 0.10);
  EXPECT_GT(axis.unreachable / volume, 0.04);
  // Step-up levels reach into what lay between the main levels.
  const LeftSplit stepped = splitOf(Strategy::PlanesParallelToFace, 1.0);
  EXPECT_NEAR(stepped.unreachable, z.unreachable, 1e-6 * volume) << "the tool's reach does not depend on the path";
  EXPECT_GT(stepped.levels, z.levels);
  EXPECT_LT(stepped.betweenLevels, 0.5 * z.betweenLevels);
}

TEST(Reach, BadInputsAreRefusedByName) {
  const fixtures::PartCase& c = slot();
  const RemovalSolid& solid = c.volume.solids.front();
  const Partition p = partition(solid, c.shapes.part, Strategy::PlanesParallelToFace);
  auto message = [&](double resolution, double allowance, int threads) {
    try {
      splitWhatIsLeft(p, solid, c.shapes.part, Cutter{}, allowance, {}, resolution, threads);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(0.01, 0.5, 0).find("resolution 0.01 mm is outside [0.1, 5]"), std::string::npos);
  EXPECT_NE(message(std::nan(""), 0.5, 0).find("resolution nan"), std::string::npos);
  EXPECT_NE(message(1.0, -1.0, 0).find("allowance -1 mm is outside"), std::string::npos);
  EXPECT_NE(message(1.0, 0.5, 1000).find("threads 1000"), std::string::npos);
  EXPECT_EQ(message(1.0, 0.5, 1), "accepted");
}
