// Material-removal simulation (roughing/removal.hpp) on cases whose answers are known in closed form.
#include "common/error.hpp"
#include "common/progress.hpp"
#include "roughing/parts.hpp"
#include "roughing/removal.hpp"
#include "roughing/roughing.hpp"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>

using namespace hsm;
using namespace hsm::roughing;

namespace {
TopoDS_Shape box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), gp_Pnt(x1, y1, z1)).Shape();
}

ToolMove move(MoveKind kind, double x, double y, double z, Eigen::Vector3d axis = Eigen::Vector3d::UnitZ()) {
  ToolMove m;
  m.kind = kind;
  m.tip = {x, y, z};
  m.axis = axis;
  return m;
}

Cutter flat(double diameter) {
  Cutter c;
  c.kind = CutterKind::Flat;
  c.diameter = diameter;
  c.cornerRadius = 0.0;
  return c;
}

Cutter ball(double diameter) {
  Cutter c;
  c.kind = CutterKind::Ball;
  c.diameter = diameter;
  c.cornerRadius = 0.5 * diameter;
  return c;
}

// A 40 × 40 block, 10 mm of stock over the part: a Ø10 flat tool 5 mm deep straight across it.
struct Slab {
  TopoDS_Shape stock = box(0, 0, 0, 40, 40, 20), part = box(0, 0, 0, 40, 40, 10);
  std::vector<ToolMove> slot = {move(MoveKind::Rapid, -10, 20, 30), move(MoveKind::Plunge, -10, 20, 15),
                                move(MoveKind::Cut, 50, 20, 15), move(MoveKind::Rapid, 50, 20, 30)};
};
// The figures two runs of one program on different thread counts share, to the last digit (sums to 1e-9).
void expectSameFigures(const RemovalResult& r, const RemovalResult& one, int threads) {
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); };
  EXPECT_TRUE(near(r.remainingVolume, one.remainingVolume)) << threads << ": " << r.remainingVolume << " " << one.remainingVolume;
  EXPECT_TRUE(near(r.inMaterialLength, one.inMaterialLength)) << threads;
  EXPECT_TRUE(near(r.gougeVolume, one.gougeVolume)) << threads;
  EXPECT_EQ(r.gougeMove, one.gougeMove) << threads;
  EXPECT_EQ(r.stickOut, one.stickOut) << threads;
  EXPECT_EQ(r.stickOutMove, one.stickOutMove) << threads;
  ASSERT_EQ(r.rapidFaults.size(), one.rapidFaults.size()) << threads;
  for (size_t f = 0; f < r.rapidFaults.size(); ++f) EXPECT_EQ(r.rapidFaults[f].move, one.rapidFaults[f].move) << threads;
  EXPECT_EQ(r.thickness, one.thickness) << threads;
}

}  // namespace

TEST(Removal, AFlatToolThroughABoxIsExact) {
  const Slab s;
  const RemovalResult r = simulateRemoval(s.slot, flat(10.0), s.stock, s.part);
  EXPECT_NEAR(r.volumeToRemove, 16000.0, 1e-6);
  // A slot 10 wide, 5 deep, 40 long: 2,000 mm³, its walls between rays and its floor on them: exact.
  EXPECT_NEAR(r.volumeToRemove - r.remainingVolume, 2000.0, 1e-6);
  EXPECT_NEAR(r.remainingShare, 87.5, 1e-8);
  EXPECT_EQ(r.gougeMove, -1);
  EXPECT_EQ(r.gougeVolume, 0.0);
  EXPECT_NEAR(r.pathLength, 15 + 60 + 15, 1e-9);
  EXPECT_NEAR(r.feedLength, 15 + 60, 1e-9);
  // In material while the tool's front is in the block: from x = -5 to about 40 of the 60 mm cut.
  EXPECT_GT(r.inMaterialLength, 40.0);
  EXPECT_LT(r.inMaterialLength, 50.0);
  // The holder clears the block's top 5 mm above the tip.
  EXPECT_NEAR(r.stickOut, 5.0, 0.2);
  // Stock left on the part's top: 10 mm, but 5 mm under the slot (a quarter of the top).
  EXPECT_NEAR(r.thicknessMax, 10.0, 1e-6);
  EXPECT_GT(r.thicknessMean, 8.0);
  EXPECT_LT(r.thicknessMean, 9.2);
}

TEST(Removal, TheStockLeftAsAClosedMeshOfBlocks) {
  const Slab s;
  RemovalSettings settings;
  settings.stockMeshStride = 2;
  const RemovalResult r = simulateRemoval(s.slot, flat(10.0), s.stock, s.part, settings);
  ASSERT_FALSE(r.stockMesh.triangles.empty());
  // Closed and outward: its volume by the divergence theorem is the stock left, 14,000 mm³ (the slot's walls
  // fall on the 0.4 mm blocks' edges).
  double volume = 0.0;
  for (const Eigen::Vector3i& t : r.stockMesh.triangles)
    volume += r.stockMesh.vertices[t[0]].dot(r.stockMesh.vertices[t[1]].cross(r.stockMesh.vertices[t[2]])) / 6.0;
  EXPECT_NEAR(volume, r.remainingVolume, 1e-6 * r.remainingVolume);
  EXPECT_NEAR(volume, 14000.0, 1e-6);
}

TEST(Removal, AnEmptyProgramLeavesEverythingAndHalfAProgramMore) {
  const Slab s;
  EXPECT_NEAR(simulateRemoval({}, flat(10.0), s.stock, s.part).remainingShare, 100.0, 1e-12);
  std::vector<ToolMove> two = s.slot;
  two.push_back(move(MoveKind::Plunge, 50, 10, 15));
  two.push_back(move(MoveKind::Cut, -10, 10, 15));
  const double whole = simulateRemoval(two, flat(10.0), s.stock, s.part).remainingShare;
  const double half = simulateRemoval(s.slot, flat(10.0), s.stock, s.part).remainingShare;
  EXPECT_GT(half, whole + 5.0);
}

TEST(Removal, ABallPlungedIntoABlockWithinHalfAPercentAndTheErrorFallsWithTheResolution) {
  // Tip 10 mm down: a cylinder of radius 5 over 5 mm and a half ball: 125π + 250π/3 mm³.
  const TopoDS_Shape stock = box(-20, -20, -20, 20, 20, 0), part = box(-20, -20, -20, 20, 20, -15);
  const std::vector<ToolMove> plunge = {move(MoveKind::Rapid, 0, 0, 10), move(MoveKind::Plunge, 0, 0, -10)};
  const double exact = 125.0 * M_PI + 250.0 * M_PI / 3.0;
  double errors[2];
  for (int k = 0; k < 2; ++k) {
    RemovalSettings settings;
    settings.resolution = k == 0 ? 0.2 : 0.1;
    const RemovalResult r = simulateRemoval(plunge, ball(10.0), stock, part, settings);
    errors[k] = std::abs(r.volumeToRemove - r.remainingVolume - exact) / exact;
  }
  EXPECT_LT(errors[0], 0.005);
  EXPECT_LT(errors[1], 0.6 * errors[0]) << "at 0.2 mm " << errors[0] << ", at 0.1 mm " << errors[1];
}

TEST(Removal, AGougeIsFoundAndLocated) {
  const Slab s;
  std::vector<ToolMove> moves = s.slot;
  moves.push_back(move(MoveKind::Rapid, 20, 30, 30));
  moves.push_back(move(MoveKind::Plunge, 20, 30, 8));  // 2 mm into the part, Ø10: 50π mm³
  moves.push_back(move(MoveKind::Rapid, 20, 30, 30));
  const RemovalResult r = simulateRemoval(moves, flat(10.0), s.stock, s.part);
  EXPECT_EQ(r.gougeMove, 5);
  EXPECT_NEAR(r.gougeAt.z(), 10.0, 2.0) << "where the tool first enters the part";
  EXPECT_NEAR(r.gougeVolume / (50.0 * M_PI), 1.0, 0.1);
}

TEST(Removal, AHolderOverAPocketNeedsTheDepthAsStickOut) {
  // A 20 × 20 pocket 12 deep in a 60 × 60 block; the Ø8 tool at its floor, its Ø32 holder over the walls.
  const TopoDS_Shape stock = box(0, 0, 0, 60, 60, 30);
  const TopoDS_Shape part = BRepAlgoAPI_Cut(stock, box(20, 20, 18, 40, 40, 30)).Shape();
  const std::vector<ToolMove> moves = {move(MoveKind::Rapid, 30, 30, 40), move(MoveKind::Plunge, 30, 30, 18.5)};
  const RemovalResult r = simulateRemoval(moves, flat(8.0), stock, part);
  EXPECT_NEAR(r.stickOut, 11.5, 0.2);
}

TEST(Removal, BadSettingsAreRefusedByName) {
  const Slab s;
  RemovalSettings settings;
  settings.resolution = 0.0;
  EXPECT_THROW(simulateRemoval(s.slot, flat(10.0), s.stock, s.part, settings), InputError);
  settings.resolution = 0.001;
  try {
    simulateRemoval(s.slot, flat(10.0), s.stock, s.part, settings);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside [0.005, 50] mm"), std::string::npos) << e.what();
  }
  settings.resolution = 0.2;
  settings.chipSection = -1.0;
  EXPECT_THROW(simulateRemoval(s.slot, flat(10.0), s.stock, s.part, settings), InputError);
  std::vector<ToolMove> bad = s.slot;
  bad[1].tip.x() = std::nan("");
  EXPECT_THROW(simulateRemoval(bad, flat(10.0), s.stock, s.part), InputError);
}

// The check on the slanted slot block: a vertical tool (Z-level roughing, S1 from the top face) cannot
// reach under the 30° overhang and leaves at least 35 % of the volume; the setup planes along the slot (S3)
// leave at most 2 % beyond the allowance layer.
TEST(Removal, TheSlantedSlotNeedsItsSetupDirection) {
  const PartAndStock block = slantedSlotBlock();
  const VolumeToRemove volume = volumeToRemove(block.stock, block.part);
  const RemovalSolid& slot = volume.solids.front();
  RemovalSettings settings;
  settings.resolution = 0.25;
  auto removal = [&](Strategy strategy) {
    const SweepResult paths = sweep(partition(slot, block.part, strategy), slot, block.part, block.stock, {});
    return simulateRemoval(paths.moves, SweepSettings().cutter, block.stock, block.part, settings);
  };
  const RemovalResult setup = removal(Strategy::SetupPlanes), zLevel = removal(Strategy::PlanesParallelToFace);
  EXPECT_GE(zLevel.remainingShare, 35.0);
  EXPECT_LE(setup.beyondAllowanceShare, 2.0) << "V_r " << setup.remainingShare << " % with the allowance layer";
  EXPECT_EQ(setup.gougeMove, -1);
  EXPECT_NEAR(setup.thicknessMean, 0.5, 0.1) << "the allowance, with the corners' few extra";
}

// A rapid straight down 5 mm into the slab's stock: a fault where it meets the stock (z 20), with the volume it
// takes out; fed through the stock from above it instead, the same material goes and no rapid cuts.
TEST(Removal, ARapidIntoTheStockIsAFaultAndFeedingItInMendsIt) {
  const Slab s;
  const std::vector<ToolMove> moves = {move(MoveKind::Rapid, 20, 20, 30), move(MoveKind::Rapid, 20, 20, 15),
                                       move(MoveKind::Cut, 30, 20, 15), move(MoveKind::Rapid, 30, 20, 30)};
  const RemovalResult r = simulateRemoval(moves, flat(10.0), s.stock, s.part);
  ASSERT_EQ(r.rapidFaults.size(), 1u);
  const RapidFault& fault = r.rapidFaults[0];
  EXPECT_EQ(fault.move, 1);
  EXPECT_NEAR(fault.at.z(), 20.0, 1.0);  // the first position that cut, within a sampling step of the stock
  EXPECT_LE(fault.along * 15.0, 10.0 + 1e-9);  // before it the tool was in the air: 10 of the move's 15 mm
  EXPECT_NEAR(fault.volume, M_PI * 25.0 * 5.0, 0.03 * M_PI * 25.0 * 5.0);
  EXPECT_NEAR(r.rapidVolume, fault.volume, 1e-9);

  const std::vector<ToolMove> mended = feedThroughStock(moves, r.rapidFaults, 1.0);
  ASSERT_EQ(mended.size(), moves.size() + 1);
  EXPECT_EQ(mended[1].kind, MoveKind::Rapid);
  EXPECT_GE(mended[1].tip.z(), 21.0 - 1e-9);  // the rapid stops a margin above the stock
  EXPECT_EQ(mended[2].kind, MoveKind::Plunge);
  EXPECT_NEAR(mended[2].tip.z(), 15.0, 1e-12);
  const RemovalResult again = simulateRemoval(mended, flat(10.0), s.stock, s.part);
  EXPECT_TRUE(again.rapidFaults.empty());
  EXPECT_NEAR(again.remainingVolume, r.remainingVolume, 1e-6);

  const RapidsMended kept = keepRapidsOutOfStock(moves, flat(10.0), s.stock, s.part, RemovalSettings{});
  EXPECT_EQ(kept.mended.size(), 1u);
  EXPECT_TRUE(simulateRemoval(kept.moves, flat(10.0), s.stock, s.part).rapidFaults.empty());
  // The slab's own slot program approaches through the air: nothing to mend.
  EXPECT_TRUE(simulateRemoval(s.slot, flat(10.0), s.stock, s.part).rapidFaults.empty());
}

TEST(Removal, FaultsOfOtherMovesAndBadThreadsAreRefused) {
  const Slab s;
  RapidFault cut;
  cut.move = 2;  // a cut, not a rapid
  EXPECT_THROW(feedThroughStock(s.slot, {cut}, 1.0), InputError);
  RapidFault beyond;
  beyond.move = 9;
  EXPECT_THROW(feedThroughStock(s.slot, {beyond}, 1.0), InputError);
  EXPECT_THROW(feedThroughStock(s.slot, {}, -1.0), InputError);
  RemovalSettings many;
  many.threads = 10000;  // would start 10,000 threads: refused by name, not a crash
  try {
    simulateRemoval(s.slot, flat(10.0), s.stock, s.part, many);
    FAIL() << "10000 threads accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("threads 10000"), std::string::npos) << e.what();
  }
}

// Rays are cut by lanes of rows, one per thread, without a barrier between positions: 1, 2 and 7 threads give
// the same figures (each lane's chips added up in the positions' order) and the same stock left. Progress is
// reported from the calling thread while the lanes work, and a cancel there stops them.
TEST(Removal, OneTwoAndSevenThreadsGiveTheSameAndACancelStopsThemAll) {
  const PartAndStock block = slantedSlotBlock();
  const VolumeToRemove volume = volumeToRemove(block.stock, block.part);
  const RemovalSolid& slot = volume.solids.front();
  std::vector<ToolMove> moves = sweep(partition(slot, block.part, Strategy::SetupPlanes), slot, block.part, block.stock, {}).moves;
  moves.push_back(move(MoveKind::Rapid, moves.back().tip.x(), moves.back().tip.y(), -100.0));  // a rapid fault, a gouge
  RemovalSettings settings;
  settings.resolution = 0.25;
  settings.stockMeshStride = 2;
  const auto run = [&](int threads) {
    settings.threads = threads;
    return simulateRemoval(moves, SweepSettings().cutter, block.stock, block.part, settings);
  };
  const RemovalResult one = run(1);
  ASSERT_FALSE(one.rapidFaults.empty());
  ASSERT_GT(one.gougeVolume, 0.0);
  const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); };
  for (int threads : {2, 7}) {
    const RemovalResult r = run(threads);
    expectSameFigures(r, one, threads);
    EXPECT_TRUE(near(r.beyondAllowanceVolume, one.beyondAllowanceVolume)) << threads;
    for (size_t f = 0; f < std::min(r.rapidFaults.size(), one.rapidFaults.size()); ++f)
      EXPECT_TRUE(near(r.rapidFaults[f].volume, one.rapidFaults[f].volume)) << threads;
    EXPECT_EQ(r.stockMesh.vertices, one.stockMesh.vertices) << threads;
  }
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<double> seen;
  settings.progress = [&](double done) {
    EXPECT_EQ(std::this_thread::get_id(), caller) << "progress reported from a worker";
    seen.push_back(done);
    return true;
  };
  run(2);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_LT(seen.front(), 1.0) << "reported only at the end";
  EXPECT_EQ(seen.back(), 1.0);
  seen.clear();
  settings.progress = [&](double done) {
    seen.push_back(done);
    return false;
  };
  EXPECT_THROW(run(2), Cancelled);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_LT(seen.front(), 1.0) << "the lanes were not stopped";
}

// Two tools in turn (a program of two operations) on the same stock: 1, 2 and 7 threads give the same figures,
// the same rest points and faults numbered through both runs; progress runs on through them to the end.
TEST(Removal, TwoToolRunsGiveTheSameOnOneTwoAndSevenThreads) {
  const PartAndStock block = slantedSlotBlock();
  const VolumeToRemove volume = volumeToRemove(block.stock, block.part);
  const RemovalSolid& slot = volume.solids.front();
  const std::vector<ToolMove> moves = sweep(partition(slot, block.part, Strategy::SetupPlanes), slot, block.part, block.stock, {}).moves;
  const size_t half = moves.size() / 2;
  std::vector<ToolRun> runs = {{{moves.begin(), moves.begin() + long(half)}, SweepSettings().cutter},
                               {{moves.begin() + long(half), moves.end()}, ball(6.0)}};
  runs.back().moves.push_back(move(MoveKind::Rapid, moves.back().tip.x(), moves.back().tip.y(), -100.0));
  const int last = static_cast<int>(moves.size());  // the rapid's index through both runs
  RemovalSettings settings;
  settings.resolution = 0.25;
  settings.restSpacing = 1.0;
  const auto run = [&](int threads) {
    settings.threads = threads;
    return simulateRemoval(runs, block.stock, block.part, settings);
  };
  const RemovalResult one = run(1);
  ASSERT_FALSE(one.rapidFaults.empty());
  EXPECT_EQ(one.rapidFaults.back().move, last);
  ASSERT_FALSE(one.rest.points.empty());
  for (int threads : {2, 7}) {
    const RemovalResult r = run(threads);
    expectSameFigures(r, one, threads);
    EXPECT_EQ(r.rest.spacing, one.rest.spacing) << threads;
    EXPECT_EQ(r.rest.points, one.rest.points) << threads;
  }
  std::vector<double> seen;
  settings.progress = [&](double done) {
    seen.push_back(done);
    return true;
  };
  run(2);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);
}
