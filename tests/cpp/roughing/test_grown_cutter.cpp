// The cutter grown by the allowance, as the sweep keeps the part's points away from the tool's centre: its
// width per height against the torus's own closed form, and the keep-outs of levels whose surface falls away
// across the plane (the unrolled offsets of a surface of revolution whose tool axes lean out from its axis).
#include "roughing/grown_cutter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace hsm::roughing;

namespace {

constexpr double kAllowance = 0.5;

Cutter paperTorus() { return Cutter{}; }  // Ø8, corner radius 1

// Distance from a point (ρ from the axis, z above the tip) to the torus end mill: the distance to its core (a
// cylinder of radius R − r standing r above the tip) less the corner radius.
double distanceToTorus(const Cutter& c, double rho, double z) {
  return std::hypot(std::max(0.0, rho - (c.radius() - c.corner())), std::max(0.0, c.corner() - z)) - c.corner();
}

// Whether a part point x across and y along the tool's line, its own height z, meets the grown cutter where
// the surface curves up by `concavity` along y and `across` along x, and falls away across x by `convexity`.
bool meets(const GrownCutter& grown, double z, double concavity, double across, double convexity, double x, double y) {
  return std::hypot(x, y) < grown.width(z + 0.5 * (y * y * concavity + x * x * (across - convexity)));
}

// Every point meeting the grown cutter lies in the disk and in the ellipse; where the ellipse is narrower than
// the disk it is within 0.06 mm of the farthest such point across.
void expectHeldAndNearlyExact(const GrownCutter& grown, double concavity, double across, double convexity, double z) {
  const double full = Cutter{}.radius() + kAllowance;
  const Ellipse e = grown.keepOut(z, convexity);
  const double disk = grown.keepOut(z);
  EXPECT_LE(e.across, disk) << "z " << z << " convexity " << convexity;
  double farthest = 0.0;  // across, of the points meeting the cutter
  for (double x = 0.0; x <= full; x += 0.011)
    for (double y = 0.0; y <= full; y += 0.011)
      if (meets(grown, z, concavity, across, convexity, x, y)) {
        farthest = std::max(farthest, x);
        ASSERT_LE(std::pow(x / e.across, 2) + std::pow(y / e.along, 2), 1.0)
            << "z " << z << " convexity " << convexity << " point " << x << ", " << y;
        ASSERT_LE(std::hypot(x, y), disk) << "z " << z << " convexity " << convexity << " point " << x << ", " << y;
      }
  if (e.across < disk) {
    EXPECT_LT(e.across, farthest + 0.06) << "z " << z << " convexity " << convexity;
  }
}

}  // namespace

TEST(GrownCutter, WidthIsTheTorusGrownByTheAllowance) {
  const Cutter c = paperTorus();
  const GrownCutter grown(c, kAllowance, 0.0);
  EXPECT_EQ(grown.width(-kAllowance - 0.01), 0.0);
  for (double z = -kAllowance + 0.001; z < c.corner() + 1.0; z += 0.013) {
    // The farthest ρ at which the point is within the allowance of the torus, by bisection on its distance.
    double lo = 0.0, hi = c.radius() + kAllowance + 1.0;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (distanceToTorus(c, mid, z) < kAllowance ? lo : hi) = mid;
    }
    EXPECT_NEAR(grown.width(z), lo, 1e-9) << "z " << z;
    EXPECT_NEAR(grown.keepOut(z), lo, 0.0021) << "z " << z;  // the scan's step
  }
}

TEST(GrownCutter, KeepOutOfAFlatLevelIsItsDisk) {
  const GrownCutter flat(paperTorus(), kAllowance, 0.0), concave(paperTorus(), kAllowance, 0.03);
  for (double z : {-0.3, 0.0, 0.4, 0.9, 2.0}) {
    const Ellipse e = flat.keepOut(z, 0.0);
    EXPECT_EQ(e.across, flat.keepOut(z));
    EXPECT_EQ(e.along, flat.keepOut(z));
    // A surface that falls away across slower than it curves up: the disk too.
    const Ellipse c = concave.keepOut(z, 0.02);
    EXPECT_EQ(c.across, concave.keepOut(z));
    EXPECT_EQ(c.along, concave.keepOut(z));
  }
}

TEST(GrownCutter, DiskAndEllipseHoldEveryPointMeetingTheCutterAndAreNearlyExactAcross) {
  const double concavity = 0.01;
  const GrownCutter grown(paperTorus(), kAllowance, concavity);
  for (double convexity : {0.02, 0.05, 0.09})
    for (double z : {-0.2, 0.3, 0.8, 1.0, 1.25, 1.5}) expectHeldAndNearlyExact(grown, concavity, concavity, convexity, z);
  // In the corner, 1 mm above the tip where the level falls away as a channel's near its inlet (ρ 12 mm,
  // axis leaning out 0.9): a point 4.4 mm beside the line stands 0.7 mm lower along it. Lower in the corner,
  // more so.
  const double inlet = 0.9 / 12.0;
  EXPECT_LT(grown.keepOut(1.0, inlet).across, grown.keepOut(1.0) - 0.1);
  EXPECT_LT(grown.keepOut(0.5, inlet).across, grown.keepOut(0.5) - 0.3);
}

TEST(GrownCutter, AMeridianCurvingUpAlongYLeavesTheFallAwayAcrossXWhole) {
  // The hub's offsets: the meridian curves up by 0.03/mm along y, round the axis the level falls away by
  // 0.02/mm across x and does not curve up. Taken every way, the concavity would outweigh the fall-away and
  // leave the disk; taken along y alone, the ellipse is narrower across.
  const double concavity = 0.03, convexity = 0.02;
  const GrownCutter anyWay(paperTorus(), kAllowance, concavity), alongY(paperTorus(), kAllowance, concavity, 0.0);
  EXPECT_EQ(anyWay.keepOut(0.3, convexity).across, anyWay.keepOut(0.3));
  EXPECT_LT(alongY.keepOut(0.3, convexity).across, alongY.keepOut(0.3) - 0.1);
  for (double c : {0.01, 0.02, 0.05})
    for (double z : {-0.3, 0.0, 0.3, 0.8, 1.0}) expectHeldAndNearlyExact(alongY, concavity, 0.0, c, z);
  // Curving up across more than it falls away: the disk.
  const GrownCutter both(paperTorus(), kAllowance, concavity, 0.025);
  EXPECT_EQ(both.keepOut(0.3, convexity).across, both.keepOut(0.3));
}

TEST(GrownCutter, BandsOfALevelFallingAwayHaveTheirEllipsesBelowTheCorner) {
  const Cutter c = paperTorus();
  const GrownCutter grown(c, kAllowance, 0.0);
  const double extra = 0.06, full = c.radius() + kAllowance;
  const std::vector<Band> flat = grown.bands(8, 0.005, extra);
  ASSERT_FALSE(flat.empty());
  EXPECT_NEAR(flat.back().from, c.corner(), 1e-9) << "on a flat level the last band starts at the corner";
  for (const Band& b : flat) EXPECT_TRUE(b.convex.empty());

  const double convexity = 0.07;
  const std::vector<Band> convex = grown.bands(8, 0.005, extra, convexity);
  // The same heights, below the corner in bands at most 0.25 mm thick, each kept out by its top's width.
  ASSERT_GE(convex.size(), flat.size());
  EXPECT_EQ(convex.front().from, flat.front().from);
  EXPECT_NEAR(convex.back().from, c.corner(), 1e-9);
  EXPECT_EQ(convex.back().clearance, full + extra);
  EXPECT_TRUE(convex.back().convex.empty()) << "the open band keeps the full width";
  const size_t steps = static_cast<size_t>(std::floor(convexity / kConvexityStep));
  for (size_t i = 0; i + 1 < convex.size(); ++i) {
    const Band& b = convex[i];
    EXPECT_EQ(b.to, convex[i + 1].from);
    EXPECT_LE(b.to - b.from, 0.25 + 1e-9);
    EXPECT_NEAR(b.clearance, grown.keepOut(b.to) + extra, 1e-12);
    ASSERT_EQ(b.convex.size(), steps);
    // Each step's ellipse holds its own keep-out's grown by `extra` every way, as the band's disk is.
    const Ellipse e = grown.keepOut(b.to, steps * kConvexityStep), held = b.convex.back();
    EXPECT_LE(held.across, b.clearance + 1e-12);
    for (double t = 0.0; t < 2.0 * M_PI; t += 0.01) {
      const double x = e.across * std::cos(t), y = e.along * std::sin(t);
      const double nx = x / (e.across * e.across), ny = y / (e.along * e.along), n = std::hypot(nx, ny);
      const double gx = x + extra * nx / n, gy = y + extra * ny / n;
      EXPECT_LE(std::pow(gx / held.across, 2) + std::pow(gy / held.along, 2), 1.0 + 1e-12) << "band to " << b.to;
    }
  }
  // However far the level curves up along y, its thin bands stay bounded.
  const GrownCutter steep(c, kAllowance, 2.0, 0.0);
  EXPECT_LE(steep.bands(8, 0.005, extra, 0.01).size(), 8u + 32u + 1u);
  // The corner's top falls back lower into it beside the tool: narrower across than the flutes.
  EXPECT_LT(convex[convex.size() - 2].convex.back().across, full + extra - 0.1);
}
