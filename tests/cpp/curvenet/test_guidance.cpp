#include "common/error.hpp"
#include "curvenet/curvenet.hpp"
#include "curves.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace hsm;
using namespace hsm::curvenet;
using hsm::test::line;
using hsm::test::planCurve;
using hsm::test::yAt;

namespace {
// A boundary with inflections at x = 50 and 100 and a tight turn near x = 25 (plan radius 100²/(4π²·8) ≈ 31.7 mm
// per unit amplitude: 8 mm amplitude gives R ≈ 31.7 mm).
double wavy(double x) { return 8.0 * std::sin(2.0 * M_PI * x / 100.0); }
}  // namespace

TEST(GuidanceCurves, FourAreasMedianAndOneCurvePerHalf) {
  Boundaries b{planCurve(0, 150, wavy), line(0, 150, 40)};
  GuidanceSettings settings;
  const GuidanceResult result = guidanceCurves(b, settings);
  const CurveNet& net = result.net;
  ASSERT_EQ(net.curves.size(), 5u);
  EXPECT_EQ(net.curves[2].label, "Cmed");
  EXPECT_EQ(net.elementaryAreas().size(), 4u);
  // Step 1: the median is halfway in every plane.
  for (double x : {10.0, 37.5, 75.0, 140.0}) EXPECT_NEAR(yAt(net.curves[2].curve, x), 0.5 * (wavy(x) + 40), 0.02);
  // Step 3, half 1: the median (smaller waves) has the larger smallest radius, so it starts; K 0.75 → 3/4 to B1.
  EXPECT_EQ(result.report.half1.start, "Cmed");
  EXPECT_GT(result.report.half1.startMinRadius, result.report.half1.targetMinRadius);
  const double ymed = 0.5 * (wavy(60) + 40);
  EXPECT_NEAR(yAt(net.curves[1].curve, 60), ymed + 0.75 * (wavy(60) - ymed), 0.03);
  // Half 2: B2 is a line, so it starts.
  EXPECT_EQ(result.report.half2.start, "B2");
  EXPECT_NEAR(yAt(net.curves[3].curve, 60), 40 + 0.75 * (ymed - 40), 0.03);
  // Step 2: the inflection points became planes, and the spacing adapted (never above P0).
  bool at50 = false, at100 = false;
  for (double s : result.report.inflectionStations) {
    at50 = at50 || std::abs(s - 50) < 0.1;
    at100 = at100 || std::abs(s - 100) < 0.1;
  }
  EXPECT_TRUE(at50 && at100) << ::testing::PrintToString(result.report.inflectionStations);
  EXPECT_LE(result.report.largestStep, settings.net.step + 1e-9);
  EXPECT_GT(result.report.smallestStep, 0.0);
}

TEST(GuidanceCurves, SmallRadiusRefinesThePlanes) {
  // A 3 mm-radius-scale bump: the planes near it are spaced by about R/2, well under P0.
  auto bump = [](double x) { return 6.0 * std::exp(-std::pow((x - 50.0) / 4.0, 2)); };
  Boundaries b{planCurve(0, 100, bump, {}, 801), line(0, 100, 30)};
  const GuidanceResult result = guidanceCurves(b, GuidanceSettings{});
  EXPECT_LT(result.report.smallestStep, 2.0);
  size_t nearBump = 0;
  for (double s : result.net.stations) nearBump += std::abs(s - 50.0) < 8.0;
  EXPECT_GE(nearBump, 8u);  // at 5 mm there would be 3
}

TEST(GuidanceCurves, TwoStraightGuidesNeedNoCurve) {
  Boundaries b{line(0, 100, 0), line(0, 100, 30)};
  const GuidanceResult result = guidanceCurves(b, GuidanceSettings{});
  EXPECT_TRUE(result.report.half1.skipped);
  EXPECT_TRUE(result.report.half2.skipped);
  ASSERT_EQ(result.net.curves.size(), 3u);
  EXPECT_EQ(result.net.curves[1].label, "Cmed");
}

TEST(GuidanceCurves, BadRatiosAreRefused) {
  Boundaries b{line(0, 100, 0), line(0, 100, 30)};
  GuidanceSettings settings;
  settings.k = 1.0;
  EXPECT_THROW(guidanceCurves(b, settings), InputError);
  settings.k = 0.75;
  settings.kMedian = 0.0;
  EXPECT_THROW(guidanceCurves(b, settings), InputError);
  settings.kMedian = 0.5;
  settings.minStep = 10.0;  // above P0
  EXPECT_THROW(guidanceCurves(b, settings), InputError);
}
