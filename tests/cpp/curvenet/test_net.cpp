#include "common/error.hpp"
#include "curvenet/curvenet.hpp"
#include "curvenet/regions.hpp"
#include "curves.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <gp_Pln.hxx>
#include <gtest/gtest.h>

#include <cmath>

using namespace hsm;
using namespace hsm::curvenet;
using hsm::test::line;
using hsm::test::planCurve;
using hsm::test::yAt;

namespace {
// Two parallel lines 28 mm apart: with the default 2 mm gap the paper's counts follow from (1−K)^j·28 ≥ 2.
Boundaries parallel(double width = 28.0) { return {line(0, 140, 0), line(0, 140, width)}; }

std::vector<double> yAcross(const CurveNet& net, double x) {
  std::vector<double> ys;
  for (const NetCurve& c : net.curves) ys.push_back(yAt(c.curve, x));
  return ys;
}

std::vector<size_t> composedSizes(const CurveNet& net) {
  std::vector<size_t> sizes;
  for (const auto& ma : net.composedAreas()) sizes.push_back(ma.size());
  return sizes;
}
}  // namespace

TEST(CurveNet, FromB1TowardsB2StopsBeforeTheMinimumGap) {
  const CurveNet net = curveNet(parallel(), 0.25, NetMode::B1ToB2, NetSettings{});
  ASSERT_EQ(net.curves.size(), 11u);  // B1, 9 curves (Table 1, K = 0.25), B2
  const auto ys = yAcross(net, 70.0);
  for (size_t j = 1; j + 1 < ys.size(); ++j) EXPECT_NEAR(28.0 - ys[j], 28.0 * std::pow(0.75, j), 1e-6) << j;
  EXPECT_GE(28.0 - ys[9], 2.0);                     // kept: 2.1 mm from B2
  EXPECT_LT(28.0 * std::pow(0.75, 10), 2.0);        // the tenth would be at 1.6 mm: dropped
  EXPECT_EQ(net.curves[1].label, "C1.1");
  EXPECT_EQ(net.curves[1].from, "B1");
  EXPECT_EQ(net.curves[2].from, "C1.1");
  EXPECT_EQ(composedSizes(net), (std::vector<size_t>{2, 3, 4, 5, 6, 7, 8, 9, 10}));
}

TEST(CurveNet, KThreeQuartersGivesOneCurve) {
  const CurveNet forward = curveNet(parallel(), 0.75, NetMode::B1ToB2, NetSettings{});
  const CurveNet backward = curveNet(parallel(), 0.75, NetMode::B2ToB1, NetSettings{});
  ASSERT_EQ(forward.curves.size(), 3u);
  ASSERT_EQ(backward.curves.size(), 3u);
  EXPECT_NEAR(yAt(forward.curves[1].curve, 10.0), 21.0, 1e-6);
  EXPECT_NEAR(yAt(backward.curves[1].curve, 10.0), 7.0, 1e-6);
  EXPECT_EQ(backward.curves[1].label, "C2.1");
}

TEST(CurveNet, MedianNetsReproduceTable2Counts) {
  // K 0.25: 13 curves (median + 6 per half), K 0.5: 5, K 0.75: 3; areas 2, 4, … 2n.
  const std::pair<double, size_t> expected[] = {{0.25, 13}, {0.5, 5}, {0.75, 3}};
  for (const auto& [k, count] : expected) {
    for (NetMode mode : {NetMode::MedianToBoundaries, NetMode::BoundariesToMedian}) {
      const CurveNet net = curveNet(parallel(), k, mode, NetSettings{});
      EXPECT_EQ(net.curves.size() - 2, count) << "K " << k << " " << netModeName(mode);
      const auto ys = yAcross(net, 33.0);
      for (size_t i = 1; i < ys.size(); ++i) EXPECT_GT(ys[i], ys[i - 1]) << "curves out of order";
      const auto sizes = composedSizes(net);
      for (size_t j = 0; j < sizes.size(); ++j) EXPECT_EQ(sizes[j], 2 * (j + 1));
      EXPECT_EQ(sizes.back(), count + 1);
    }
  }
}

TEST(CurveNet, MedianToBoundariesStartsAtTheMedian) {
  const CurveNet net = curveNet(parallel(), 0.25, NetMode::MedianToBoundaries, NetSettings{});
  const auto ys = yAcross(net, 50.0);
  const size_t median = 7;
  EXPECT_EQ(net.curves[median].label, "Cmed");
  EXPECT_NEAR(ys[median], 14.0, 1e-6);
  EXPECT_NEAR(ys[median - 1], 14.0 - 0.25 * 14.0, 1e-6);  // C1.1: a quarter of the way to B1
  EXPECT_EQ(net.curves[median - 1].label, "C1.1");
  EXPECT_EQ(net.curves[median + 1].label, "C2.1");
}

TEST(CurveNet, TouchingBoundariesShareAPointAndTheNetStillGrows) {
  // B2 touches B1 (y = 0) at x = 70.
  Boundaries b{line(0, 140, 0), planCurve(0, 140, [](double x) { return 28.0 * std::pow((x - 70.0) / 70.0, 2); })};
  NetSettings settings;
  settings.step = 4.0;
  const CurveNet net = curveNet(b, 0.5, NetMode::Median, settings);
  EXPECT_NEAR(yAt(net.curves[1].curve, 70.0), 0.0, 0.02);
  bool warned = false;
  for (const auto& w : net.warnings) warned = warned || w.find("pinch") != std::string::npos;
  EXPECT_TRUE(warned);
  // The planes narrower than 7 mm (a quarter of 28) are pinches; elsewhere the net grows while the gap to B2
  // stays above 2 mm: 0.75^j · 7 ≥ 2 for j ≤ 4 at the narrowest plane kept.
  const CurveNet grown = curveNet(b, 0.25, NetMode::B1ToB2, settings);
  EXPECT_GE(grown.curves.size(), 2u + 4u);
  for (const NetCurve& c : grown.curves) EXPECT_NEAR(yAt(c.curve, 70.0), 0.0, 0.02) << c.label;
}

TEST(CurveNet, CrossingBoundariesAreRefusedWithThePlace) {
  Boundaries b{line(0, 140, 10), planCurve(0, 140, [](double x) { return x / 7.0; })};  // cross at x = 70
  try {
    curveNet(b, 0.5, NetMode::Median, NetSettings{});
    FAIL() << "crossing boundaries were accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("cross near 7"), std::string::npos) << error.what();
  }
}

TEST(CurveNet, DifferentExtentsCoverTheCommonPartWithAWarning) {
  Boundaries b{line(0, 140, 0), line(20, 100, 28)};
  const CurveNet net = curveNet(b, 0.5, NetMode::Median, NetSettings{});
  EXPECT_DOUBLE_EQ(net.stations.front(), 20.0);
  EXPECT_DOUBLE_EQ(net.stations.back(), 100.0);
  ASSERT_FALSE(net.warnings.empty());
  EXPECT_NE(net.warnings.front().find("different extents"), std::string::npos);
}

TEST(CurveNet, APlaneCuttingABoundaryTwiceUsesTheCutThatContinuesTheCurve) {
  // B1 folds back between x = 60 and x = 50 (an S seen from above), 10 mm up.
  geometry::PointArray p(12, 3);
  p << 0, 0, 0, 30, 0, 0, 55, 0, 0, 61, 1, 0, 63, 4, 0, 61, 7, 0, 55, 8.5, 0, 51, 10, 0, 53, 11.5, 0, 60, 12, 0,
      80, 12, 0, 140, 12, 0;
  Boundaries b{geometry::interpolatePoints(p), line(0, 140, 40)};
  NetSettings settings;
  settings.direction = Eigen::Vector3d::UnitX();
  const CurveNet net = curveNet(b, 0.5, NetMode::Median, settings);
  bool warned = false;
  for (const auto& w : net.warnings) warned = warned || w.find("more than once") != std::string::npos;
  EXPECT_TRUE(warned);
  // Along X the median rises from the B1 branch at y ≈ 0 to the branch at y ≈ 12, monotonically in the planes.
  const NetCurve& median = net.curves[1];
  EXPECT_NEAR(median.points(0, 1), 20.0, 1e-6);
  EXPECT_NEAR(median.points(median.points.rows() - 1, 1), 26.0, 0.1);
  for (Eigen::Index i = 1; i < median.points.rows(); ++i) EXPECT_GE(median.points(i, 1), median.points(i - 1, 1) - 0.5);
}

TEST(CurveNet, AreasOfTheBottomFace) {
  // Flat bottom 140 × 28 between the two lines: K 0.5 with the median gives 2 regions of 140 × 14.
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), 0, 140, 0, 28).Face();
  NetSettings settings;
  settings.face = face;
  const CurveNet net = curveNet(parallel(), 0.75, NetMode::MedianToBoundaries, settings);
  ASSERT_EQ(net.curves.size(), 5u);  // B1, C1.1, Cmed, C2.1, B2
  const auto regions = areaRegions(net, face);
  ASSERT_EQ(regions.size(), 4u);
  const double widths[] = {3.5, 10.5, 10.5, 3.5};  // 14 · (1 − 0.75) next to the boundaries
  for (size_t i = 0; i < regions.size(); ++i) EXPECT_NEAR(regions[i].surfaceArea, 140.0 * widths[i], 1e-3) << i;
}

TEST(CurveNet, ANetThatCouldNotEndIsRefusedBeforeAnyCurveIsBuilt) {
  NetSettings settings;
  settings.minGap = 0.0;  // no gap: the net would halve the distance for ever
  EXPECT_THROW(curveNet(parallel(), 0.5, NetMode::B1ToB2, settings), hsm::InputError);
  settings.minGap = 1e9;  // wider than the area: every plane a pinch, the stop rule blind
  EXPECT_THROW(curveNet(parallel(), 0.5, NetMode::B1ToB2, settings), hsm::InputError);
  settings.minGap = 0.01;
  settings.maxCurvesPerNet = 5;  // K = 0.5 needs about log2(width / 0.01) curves
  try {
    curveNet(parallel(), 0.5, NetMode::B1ToB2, settings);
    ADD_FAILURE() << "no error";
  } catch (const hsm::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("use K of at least"), std::string::npos) << error.what();
  }
}
