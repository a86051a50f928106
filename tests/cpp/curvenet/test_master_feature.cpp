// Curve nets on the real test part: the curve counts of the paper's Tables 1 and 2 and the 4-step method.
#include "curvenet/curvenet.hpp"
#include "curvenet/regions.hpp"
#include "geometry/bspline.hpp"
#include "support/master_feature.hpp"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <gtest/gtest.h>

using namespace hsm;
using namespace hsm::curvenet;

namespace {
constexpr auto feature = test::masterFeature;  // loaded once per program

NetSettings onBottom() {
  NetSettings settings;
  settings.face = feature().bottom;
  return settings;
}

size_t intermediates(const CurveNet& net) { return net.curves.size() - 2; }
}  // namespace

TEST(MasterFeatureNets, Table1CountsFromEitherBoundary) {
  const Boundaries b{feature().boundary1, feature().boundary2};
  EXPECT_EQ(intermediates(curveNet(b, 0.25, NetMode::B1ToB2, onBottom())), 9u);
  EXPECT_EQ(intermediates(curveNet(b, 0.25, NetMode::B2ToB1, onBottom())), 9u);
  EXPECT_EQ(intermediates(curveNet(b, 0.75, NetMode::B1ToB2, onBottom())), 1u);
  EXPECT_EQ(intermediates(curveNet(b, 0.75, NetMode::B2ToB1, onBottom())), 1u);
}

TEST(MasterFeatureNets, Table2CountsFromTheBoundariesToTheMedian) {
  const Boundaries b{feature().boundary1, feature().boundary2};
  EXPECT_EQ(intermediates(curveNet(b, 0.25, NetMode::BoundariesToMedian, onBottom())), 13u);
  EXPECT_EQ(intermediates(curveNet(b, 0.5, NetMode::BoundariesToMedian, onBottom())), 5u);
  EXPECT_EQ(intermediates(curveNet(b, 0.75, NetMode::BoundariesToMedian, onBottom())), 3u);
}

TEST(MasterFeatureNets, CurvesLieOnTheBottomFaceWithinTheFitTolerance) {
  const Boundaries b{feature().boundary1, feature().boundary2};
  const CurveNet net = curveNet(b, 0.5, NetMode::MedianToBoundaries, onBottom());
  EXPECT_EQ(net.direction, Eigen::Vector3d::UnitX());  // the length direction, as in the paper
  for (const NetCurve& c : net.curves) {
    EXPECT_LE(c.fitDeviation, 0.01) << c.label;
    if (c.role != CurveRole::Boundary) {
      EXPECT_EQ(c.curve->Degree(), 5) << c.label;
    }
  }
}

TEST(MasterFeatureNets, FourStepMethodStartsEachHalfFromTheSmootherGuide) {
  GuidanceSettings settings;
  settings.net = onBottom();
  const GuidanceResult result = guidanceCurves({feature().boundary1, feature().boundary2}, settings);
  ASSERT_EQ(result.net.curves.size(), 5u);
  // Boundary 1 has the small-radius bump: the median starts half 1; boundary 2 is smoother than the median.
  EXPECT_EQ(result.report.half1.start, "Cmed");
  EXPECT_EQ(result.report.half2.start, "B2");
  EXPECT_LT(result.report.smallestStep, 2.0);  // refined at the bump
  EXPECT_GE(result.report.inflectionStations.size(), 3u);

  // The four elementary areas tile the bottom face.
  const auto regions = areaRegions(result.net, feature().bottom);
  GProp_GProps props;
  BRepGProp::SurfaceProperties(feature().bottom, props);
  double total = 0.0;
  for (const auto& region : regions) {
    EXPECT_GT(region.surfaceArea, 0.05 * props.Mass());
    total += region.surfaceArea;
  }
  EXPECT_NEAR(total, props.Mass(), 1e-3 * props.Mass());
}
