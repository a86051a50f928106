// The level's outlines simplified: every point they had stays within the tolerance of what is left, where
// Clipper's own cleaning lets a gently curved outline fall far inside it.
#include "roughing/flat.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace hsm::roughing;

namespace {
// A closed outline: an arc of radius `radius` mm over `span` mm, points `spacing` mm apart, closed by its chord.
cl::Path flatArc(double radius, double span, double spacing) {
  cl::Path path;
  const double half = 0.5 * span / radius;
  const int points = static_cast<int>(std::ceil(span / spacing));
  for (int k = 0; k <= points; ++k) {
    const double a = -half + 2.0 * half * k / points;
    path.push_back({static_cast<cl::cInt>(std::llround(radius * std::sin(a) * kScale)),
                    static_cast<cl::cInt>(std::llround(radius * std::cos(a) * kScale))});
  }
  return path;
}

// Mm from q to the closed path's nearest edge.
double distanceTo(const cl::IntPoint& q, const cl::Path& path) { return distanceToBoundary(q, cl::Paths{path}); }
}  // namespace

TEST(Simplify, KeepsEveryPointWithinTheToleranceOnAGentleArc) {
  const cl::Path arc = flatArc(500.0, 40.0, 0.25);
  cl::Paths ours{arc};
  simplify(ours, 0.01);
  ASSERT_EQ(ours.size(), 1u);
  EXPECT_LT(ours[0].size(), arc.size() / 4);  // it does drop points
  double worst = 0.0;
  for (const cl::IntPoint& q : arc) worst = std::max(worst, distanceTo(q, ours[0]));
  EXPECT_LE(worst, 0.0101);
  EXPECT_GT(worst, 0.002);  // and uses the room it has

  cl::Paths clipper{arc};  // what the sweep used to do
  cl::CleanPolygons(clipper, 0.01 * kScale);
  ASSERT_EQ(clipper.size(), 1u);
  double clipperWorst = 0.0;
  for (const cl::IntPoint& q : arc) clipperWorst = std::max(clipperWorst, distanceTo(q, clipper[0]));
  EXPECT_GT(clipperWorst, 0.05);
}

TEST(Simplify, DropsPathsWithoutArea) {
  cl::Paths paths{{{0, 0}, {static_cast<cl::cInt>(kScale), 0}, {static_cast<cl::cInt>(2 * kScale), 0}},
                  {{0, 0}, {0, 0}, {0, 0}},
                  {{0, 0}, {static_cast<cl::cInt>(kScale), 0}}};
  simplify(paths, 0.01);
  EXPECT_TRUE(paths.empty());
}

TEST(Simplify, KeepsTheCornersOfASquare) {
  const auto mm = [](double v) { return static_cast<cl::cInt>(v * kScale); };
  cl::Paths square{{{0, 0}, {mm(5), 0}, {mm(10), 0}, {mm(10), mm(5)}, {mm(10), mm(10)}, {0, mm(10)}}};
  simplify(square, 0.01);
  ASSERT_EQ(square.size(), 1u);
  EXPECT_EQ(square[0].size(), 4u);
  EXPECT_NEAR(std::abs(area(square)), 100.0, 1e-9);
}
