#include "common/error.hpp"
#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace hsm;
using namespace hsm::roughing;

namespace {
// Surfaces (the paper's faces: B-rep faces of one surface count once) of a class.
int count(const RemovalSolid& s, FaceClass c) {
  std::vector<bool> seen(static_cast<size_t>(s.groupCount()), false);
  int n = 0;
  for (size_t i = 0; i < s.faceClasses.size(); ++i)
    if (s.faceClasses[i] == c && !seen[static_cast<size_t>(s.faceGroups[i])]) {
      seen[static_cast<size_t>(s.faceGroups[i])] = true;
      ++n;
    }
  return n;
}

// Each slice starts where it should: the nearest point of slice k to the reference face is k·step away (the
// slicing surfaces are offsets of it, not just any cut that keeps the volume).
void expectOffsetLayers(const RemovalSolid& s, const Partition& p, double tolerance) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(s.solid, TopAbs_FACE, faces);
  ASSERT_GT(p.referenceFace, 0);
  // The reference surface untrimmed (a slab far from the inlet annulus is k·step from its plane, not from the
  // annulus), within ±1000 mm where it is unbounded.
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(faces(p.referenceFace)));
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  auto bounded = [](double x) { return std::clamp(x, -1e3, 1e3); };
  const TopoDS_Face reference = BRepBuilderAPI_MakeFace(surface, bounded(u0), bounded(u1), bounded(v0), bounded(v1), 1e-7);
  for (const SubVolume& sub : p.subVolumes) {
    BRepExtrema_DistShapeShape distance(sub.shape, reference);
    ASSERT_TRUE(distance.IsDone());
    EXPECT_NEAR(distance.Value(), sub.slice * p.step, tolerance) << strategyName(p.strategy) << " slice " << sub.slice;
  }
}

const PartAndStock& slot() {
  static const PartAndStock shapes = slantedSlotBlock();
  return shapes;
}

const VolumeToRemove& slotVolume() {
  static const VolumeToRemove v = volumeToRemove(slot().stock, slot().part);
  return v;
}
}  // namespace

TEST(Roughing, TheSlantedSlotsVolumeIsItsClosedFormWithItsFaceClasses) {
  const VolumeToRemove& v = slotVolume();
  ASSERT_EQ(v.solids.size(), 1u);
  EXPECT_NEAR(v.volume, slantedSlotVolume({}), 1e-6 * v.volume);  // 16 × 24 × 40 = 15360 mm³
  EXPECT_NEAR(v.stockVolume - v.partVolume, v.volume, 1e-6 * v.volume);
  const RemovalSolid& s = v.solids.front();
  ASSERT_EQ(s.faceClasses.size(), 6u);
  EXPECT_EQ(count(s, FaceClass::Crossable), 3);        // the mouth in the top face, both open ends
  EXPECT_EQ(count(s, FaceClass::FacingCrossable), 1);  // the floor sees the mouth
  EXPECT_EQ(count(s, FaceClass::NotCrossable), 2);     // the walls see each other
}

TEST(Roughing, PlanesGiveSlabsThatAddUpToTheVolume) {
  const RemovalSolid& s = slotVolume().solids.front();
  // S1 from the mouth (the top plane) down: the floor's lowest corner is 30 − 24·cos 30° − 8·sin 30° = 5.22 mm
  // high, so 24.78 mm of depth: ceil(24.78 / 8) = 4 slabs.
  const Partition planes = partition(s, slot().part, Strategy::PlanesParallelToFace);
  EXPECT_EQ(planes.subVolumes.size(), 4u);
  EXPECT_NEAR(planes.volume, s.volume, 1e-6 * s.volume);
  EXPECT_NEAR(planes.subVolumes.front().surface.direction.z(), -1.0, 1e-9);
  ASSERT_FALSE(planes.subVolumes.front().axisDirections.empty());
  EXPECT_NEAR(planes.subVolumes.front().axisDirections.front().z(), 1.0, 1e-6);  // the tool axis points up, out
  expectOffsetLayers(s, planes, 1e-6);
  // S5 from the floor along the slot's axis: 24 + 8·tan 30° = 28.62 mm: 4 slabs.
  const Partition floor = partition(s, slot().part, Strategy::HubOffsets, {4.0});
  EXPECT_EQ(floor.subVolumes.size(), 8u);  // ceil(28.62 / 4)
  EXPECT_NEAR(floor.volume, s.volume, 1e-6 * s.volume);
  expectOffsetLayers(s, floor, 1e-6);
  // The tool axis stands on the floor, along the slot's axis, away from the floor.
  ASSERT_FALSE(floor.subVolumes.back().axisDirections.empty());
  EXPECT_NEAR(floor.subVolumes.back().axisDirections.front().dot(Eigen::Vector3d(0.5, 0.0, std::sqrt(0.75))), 1.0, 1e-6);
}

TEST(Roughing, TheSetupDirectionOfTheSlantedSlotIsItsAxis) {
  const RemovalSolid& s = slotVolume().solids.front();
  PartitionSettings settings;
  settings.setupResolutionDeg = 5.0;
  settings.setupGrid = 1.5;
  const auto [direction, reach] = setupDirection(s, slot().part, settings);
  const Eigen::Vector3d axis(std::sin(M_PI / 6), 0.0, std::cos(M_PI / 6));
  EXPECT_GT(direction.dot(axis), std::cos(6.0 * M_PI / 180.0)) << direction.transpose();
  EXPECT_GT(reach, 0.97);
  // Straight down Z the overhang is out of reach: under the overhanging wall (24 − 8·tan 30° = 19.38 mm long
  // along the axis) the vertical from its top edge meets the floor 19.38·tan 30° = 11.19 mm across, hiding a
  // triangle of 108.4 mm² of the 16 × 24 = 384 mm² section: 71.8 % is reachable.
  const double fromAbove = reachableShare(s, slot().part, Eigen::Vector3d::UnitZ(), settings);
  EXPECT_NEAR(fromAbove, 0.718, 0.02);
  EXPECT_THROW(reachableShare(s, slot().part, Eigen::Vector3d::Zero(), settings), InputError);
  const Partition setup = partition(s, slot().part, Strategy::SetupPlanes, settings);
  EXPECT_NEAR(setup.volume, s.volume, 1e-6 * s.volume);
  EXPECT_GE(setup.subVolumes.size(), 3u);
}

TEST(Roughing, BadInputsAreRefusedWithTheirFix) {
  const RemovalSolid& s = slotVolume().solids.front();
  EXPECT_THROW(partition(s, slot().part, Strategy::CoaxialCylinders), InputError);  // no cylindrical face
  EXPECT_THROW(partition(s, slot().part, Strategy::PlanesParallelToFace, {0.0}), InputError);
  EXPECT_THROW(partition(s, slot().part, Strategy::PlanesParallelToFace, {-3.0}), InputError);
  EXPECT_THROW(partition(s, slot().part, Strategy::PlanesParallelToFace, {100.0}), InputError);  // beyond the volume
  EXPECT_THROW(partition(s, slot().part, Strategy::PlanesParallelToFace, {1e-3}), InputError);   // too many slices
  EXPECT_THROW(volumeToRemove(slot().part, slot().part), InputError);                 // nothing to remove
  EXPECT_THROW(volumeToRemove(slot().part, slot().stock), InputError);                // stock inside the part
  EXPECT_THROW(volumeToRemove(TopoDS_Shape(), slot().part), InputError);
}

TEST(Roughing, ACutThatFailsSilentlyIsCaught) {
  // OCCT's silent failure: IsDone, and the result is the stock itself.
  const double expected = slantedSlotVolume({});
  EXPECT_NE(cutProblem(slot().stock, expected).find("not the stock's less the part's"), std::string::npos);
  EXPECT_NE(cutProblem(TopoDS_Shape(), expected).find("no solid"), std::string::npos);
  EXPECT_EQ(cutProblem(slotVolume().solids.front().solid, expected), "");
}

TEST(Roughing, TheImpellersChannelsHaveThePapersSixFaces) {
  const PartAndStock wheel = impeller();
  const VolumeToRemove v = volumeToRemove(wheel.stock, wheel.part);
  ASSERT_EQ(v.solids.size(), 7u);
  for (const RemovalSolid& channel : v.solids) {
    EXPECT_EQ(channel.groupCount(), 6);  // some surfaces are split in two B-rep faces by their seam
    EXPECT_EQ(count(channel, FaceClass::Crossable), 3);        // inlet plane, outlet cylinder, the blank's skin
    EXPECT_EQ(count(channel, FaceClass::FacingCrossable), 1);  // the hub
    EXPECT_EQ(count(channel, FaceClass::NotCrossable), 2);     // suction and pressure sides
    EXPECT_NEAR(channel.volume, v.solids.front().volume, 1e-3 * channel.volume);  // the blades are alike
  }
  const RemovalSolid& channel = v.solids.front();
  for (Strategy strategy : {Strategy::PlanesParallelToFace, Strategy::CoaxialCylinders, Strategy::StockOffsets,
                            Strategy::HubOffsets}) {
    const Partition p = partition(channel, wheel.part, strategy, {4.0});
    EXPECT_NEAR(p.volume, channel.volume, 1e-6 * channel.volume) << strategyName(strategy);
    EXPECT_GE(p.subVolumes.size(), 2u) << strategyName(strategy);
    // Offsets of surfaces of revolution are revolved offsets of a fitted meridian: within 0.02 mm.
    expectOffsetLayers(channel, p, strategy == Strategy::PlanesParallelToFace ? 1e-6 : 0.02);
    for (const SubVolume& sub : p.subVolumes) EXPECT_GT(sub.volume, 1.0) << strategyName(strategy);  // no sliver
    // The hub and the shroud are concentric arcs 12 mm apart: three layers of 4 mm either way.
    if (strategy == Strategy::StockOffsets || strategy == Strategy::HubOffsets) EXPECT_EQ(p.subVolumes.size(), 3u);
  }
}

TEST(Roughing, LongWorkReportsProgressAndCanBeCancelled) {
  const RemovalSolid& s = slotVolume().solids.front();
  std::vector<double> seen;
  PartitionSettings settings{2.0};
  settings.progress = [&](double done) { seen.push_back(done); return true; };
  partition(s, slot().part, Strategy::PlanesParallelToFace, settings);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_EQ(seen.back(), 1.0);
  // OCCT's splitter reports from 0.2 to 0.7 (our own reports are outside), and stops when asked.
  EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](double d) { return d >= 0.2 && d < 0.7; }));
  settings.progress = [](double done) { return !(done >= 0.2 && done < 0.7); };
  EXPECT_THROW(partition(s, slot().part, Strategy::PlanesParallelToFace, settings), Cancelled);
  settings.progress = [](double) { return false; };
  EXPECT_THROW(partition(s, slot().part, Strategy::PlanesParallelToFace, settings), Cancelled);
  EXPECT_THROW(partition(s, slot().part, Strategy::SetupPlanes, settings), Cancelled);
  EXPECT_THROW(volumeToRemove(slot().stock, slot().part, [](double) { return false; }), Cancelled);
}
