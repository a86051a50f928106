#include "common/error.hpp"
#include "direction/direction.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <gp_Pln.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace hsm;
using namespace hsm::direction;

namespace {
// The paper's case 1: a cylinder of radius 10 about Y, its top part (|x| ≤ 6), z up.
constexpr double kCylinder = 10.0;
TopoDS_Face cylinderTop() {
  Handle(Geom_CylindricalSurface) s =
      new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(0, 0, 0), gp::DY(), gp::DZ()), kCylinder);
  const double half = std::asin(0.6);
  return BRepBuilderAPI_MakeFace(s, -half, half, 0.0, 50.0, 1e-7).Face();
}

// Case 1 conditions: ball Ø10, Sz 0.01 mm, a_max 3 m/s². The paper gives no spindle: Z = 4 at 18,000 rpm
// keeps fz under √(4·Sz·Ro) = 0.447 mm up to 30 m/min (above it, G_p = fz·√(8·Sz·Ro − fz²) would grow as
// the machine slows down, and the model would favour the slow directions).
constexpr double kAcceleration = 3000.0;

// The paper's machine: a_max on every axis, no jerk limit (a trapezoidal controller).
kinematics::MachineModel paperMachine() {
  kinematics::MachineModel machine;
  machine.controller = kinematics::ControllerKind::LinuxCNC;
  machine.maxAcceleration = Eigen::Vector3d::Constant(kAcceleration);
  return machine;
}
const kinematics::Dynamics kPlanAxes{kAcceleration, 0.0, false};

CuttingConditions case1(double feedMmPerMin) {
  CuttingConditions c;
  c.toolRadius = 5.0;
  c.scallop = 0.01;
  c.teeth = 4;
  c.spindleSpeed = 300.0;
  c.programmedFeed = feedMmPerMin / 60.0;
  return c;
}

// Independent closed forms on the cylinder: the path is an ellipse (semi-axes R'/cos θ and R', R' = R + Ro),
// cos β = cos t / sqrt(1 − sin²t·cos²θ) at the point of angle t from the top.
double ellipseRadius(double t, double theta, double offsetRadius) {
  const double a = offsetRadius / std::abs(std::cos(theta)), b = offsetRadius;
  return std::pow(a * a * std::cos(t) * std::cos(t) + b * b * std::sin(t) * std::sin(t), 1.5) / (a * b);
}

double closedFormFitness(double t, double thetaDeg, const CuttingConditions& c) {
  const double theta = thetaDeg * M_PI / 180.0;
  const double radius = std::abs(std::cos(theta)) < 1e-12 ? 1e300 : ellipseRadius(t, theta, kCylinder + c.toolRadius);
  const double fz = std::min(c.programmedFeed, std::sqrt(radius * kAcceleration)) / (c.teeth * c.spindleSpeed);
  const double cosBeta = std::cos(t) / std::sqrt(1.0 - std::pow(std::sin(t) * std::cos(theta), 2));
  return std::sqrt(8.0 * c.scallop * c.toolRadius - fz * fz) * cosBeta * fz;
}

double closedFormOptimum(const CuttingConditions& c) {
  double bestRate = -1.0, bestAngle = 0.0;
  for (int j = 0; j < 180; ++j) {
    double rate = 1e300;
    for (int i = 0; i < 21; ++i) {  // the optimiser's points across: cell centres of a 21-wide grid
      const double t = std::asin(0.6) * (2.0 * (i + 0.5) / 21 - 1.0);
      double best = 0.0;
      for (int k = 0; k < 180; ++k) best = std::max(best, closedFormFitness(t, k, c));
      rate = std::min(rate, closedFormFitness(t, j, c) / best);
    }
    if (rate > bestRate + 1e-12) {
      bestRate = rate;
      bestAngle = j;
    }
  }
  return bestAngle;
}
}  // namespace

TEST(Direction, PathRadiusAndStepMatchTheClosedForms) {
  const auto points = sampleFace(cylinderTop(), 9, 3);
  ASSERT_EQ(points.size(), 27u);
  const CuttingConditions c = case1(6000);
  for (const SurfacePoint& m : points) {
    const double t = std::atan2(m.point.x(), m.point.z());
    EXPECT_NEAR(m.k2, -1.0 / kCylinder, 1e-9);  // convex across, straight along the axis
    for (double theta : {0.0, 30.0, 45.0, 80.0}) {
      const Performance p = performance(m, theta, c, kPlanAxes);
      EXPECT_NEAR(p.pathRadius, ellipseRadius(t, theta * M_PI / 180, kCylinder + 5.0), 1e-6) << t << " " << theta;
      EXPECT_NEAR(p.fitness, closedFormFitness(t, theta, c), 1e-9);
    }
    EXPECT_GT(performance(m, 90.0, c, kPlanAxes).pathRadius, 1e12);  // along the axis: straight
  }
  // At the top the paper's eq. 18 holds: Rc = (Rcyl + Ro)/cos²θ.
  SurfacePoint top = points[13];
  EXPECT_NEAR(top.point.x(), 0.0, 1e-9);
  EXPECT_NEAR(performance(top, 30.0, c, kPlanAxes).pathRadius, 15.0 / std::pow(std::cos(M_PI / 6), 2), 1e-6);
}

TEST(Direction, Case1TransverseAtLowFeedAlongTheAxisAtHighFeed) {
  const DirectionSettings s{21, 5, 1.0, 0.95};
  // Below √((Rcyl + Ro)·a) = 12,728 mm/min the transverse direction loses no feed and steps widest.
  const double switching = std::sqrt(15.0 * 3000.0) * 60.0;
  for (double feed : {2000.0, 6000.0, 0.99 * switching}) {
    const DirectionResult r = optimalDirection(cylinderTop(), case1(feed), paperMachine(), s);
    EXPECT_EQ(r.optimalAngleDeg, 0.0) << feed;
    EXPECT_NEAR(r.alpha, 1.0, 1e-9) << feed;
  }
  for (double feed : {1.1 * switching, 16000.0, 20000.0, 25000.0, 29000.0}) {
    const DirectionResult r = optimalDirection(cylinderTop(), case1(feed), paperMachine(), s);
    EXPECT_NE(r.optimalAngleDeg, 0.0) << feed;
    EXPECT_LE(r.optimalAngleDeg, 90.0) << feed << ": the tie between θ and 180° − θ goes to the smaller angle";
    // θ and 180° − θ are the same on a cylinder symmetric about its top line.
    const double expected = closedFormOptimum(case1(feed));
    EXPECT_LE(std::min(std::abs(r.optimalAngleDeg - expected), std::abs(r.optimalAngleDeg - (180.0 - expected))), 1.0)
        << feed << ": " << r.optimalAngleDeg << " against " << expected;
  }
  // Above the switch the optimum turns towards the axis as the feed grows; at high feed the acceptable
  // beam holds the axis direction (90°) and no longer the transverse one.
  double previous = 0.0;
  for (double feed : {14000.0, 18000.0, 24000.0, 29000.0}) {
    const double angle = optimalDirection(cylinderTop(), case1(feed), paperMachine(), s).optimalAngleDeg;
    EXPECT_GT(std::min(angle, 180.0 - angle), previous) << feed;
    previous = std::min(angle, 180.0 - angle);
  }
  const DirectionResult high = optimalDirection(cylinderTop(), case1(29000.0), paperMachine(), s);
  auto has = [](const std::vector<double>& set, double angle) {
    return std::find(set.begin(), set.end(), angle) != set.end();
  };
  EXPECT_TRUE(has(high.acceptableDeg, 90.0));
  EXPECT_FALSE(has(high.acceptableDeg, 0.0));
  const DirectionResult low = optimalDirection(cylinderTop(), case1(6000.0), paperMachine(), s);
  EXPECT_TRUE(has(low.acceptableDeg, 0.0));
  EXPECT_FALSE(has(low.acceptableDeg, 90.0));
}

TEST(Direction, TheBeamAlgorithmFindsTheLargestAlpha) {
  const DirectionResult r = optimalDirection(cylinderTop(), case1(20000.0), paperMachine(), DirectionSettings{15, 5, 0.5, 0.95});
  EXPECT_NEAR(beamAlgorithmAlpha(r.rate), r.alpha, 1e-5);
  EXPECT_LT(r.alpha, 1.0);
  // The acceptable set is every direction within the reported α at every point.
  for (double angle : r.acceptableDeg) {
    const size_t j = static_cast<size_t>(std::lround(angle / 0.5));
    EXPECT_GE(r.rate[j], r.reportedAlpha - 1e-12);
  }
}

TEST(Direction, FlatFaceTiesVerticalFaceAndTightScallopAreReported) {
  const TopoDS_Face flat = BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), 0, 100, 0, 100).Face();
  const DirectionResult r = optimalDirection(flat, case1(6000), paperMachine(), DirectionSettings{});
  EXPECT_TRUE(r.allTie);
  EXPECT_EQ(r.acceptableDeg.size(), 180u);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("flat face"), std::string::npos);

  const TopoDS_Face wall = BRepBuilderAPI_MakeFace(gp_Pln(gp_Ax3(gp::Origin(), gp::DY(), gp::DX())), 0, 50, 0, 20).Face();
  try {
    optimalDirection(wall, case1(6000), paperMachine(), DirectionSettings{});
    FAIL() << "a vertical face was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertical or undercut"), std::string::npos) << e.what();
  }
  CuttingConditions tight = case1(6000);
  tight.scallop = 0.0001;  // fz = 0.125 mm: the feed marks are 0.0004 mm, and a flat face never slows down
  try {
    optimalDirection(flat, tight, paperMachine(), DirectionSettings{});
    FAIL() << "a scallop below the feed marks was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too small for fz"), std::string::npos) << e.what();
  }
  EXPECT_THROW(optimalDirection(flat, case1(6000), paperMachine(), DirectionSettings{50, 50, 2.0, 0.95}), InputError);
}

TEST(Direction, PredictedTimeOfPlanesOnASquareCountsPathAndReversals) {
  const TopoDS_Face square = BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), 0, 100, 0, 100).Face();
  const CuttingConditions c = case1(6000);
  kinematics::MachineModel machine = paperMachine();  // an 840D in SOFT: the plane's stop and start are S-curves
  machine.controller = kinematics::ControllerKind::Siemens840D;
  machine.maxJerk = Eigen::Vector3d::Constant(5000.0);
  const DirectionResult r = optimalDirection(square, c, machine, DirectionSettings{});
  // Flat: every plane steps p1 = √(8·Sz·Ro − fz²) at the programmed feed; 100/p1 planes, each with a run-out
  // of a tool radius at both ends and one stop-and-go (jerk-limited at 5 m/s³: 2·√(v/J)).
  const double fz = c.programmedFeedPerTooth(), p1 = std::sqrt(8.0 * c.scallop * c.toolRadius - fz * fz);
  const double perPlane = 2.0 * c.toolRadius / c.programmedFeed + 2.0 * std::sqrt(c.programmedFeed / 5000.0);
  const double expected = 100.0 * 100.0 / (p1 * c.programmedFeed) + 100.0 / p1 * perPlane;
  EXPECT_NEAR(r.predictedTime[0], expected, 1e-6 * expected);
  EXPECT_NEAR(r.predictedTime[90], expected, 1e-6 * expected);
  EXPECT_GT(r.predictedTime[45], r.predictedTime[0] + 0.3 * 100.0 / p1 * perPlane);  // 141 mm of planes across
  EXPECT_EQ(r.fastestAngleDeg, 0.0);  // 0° and 90° tie: the one nearest X
}

TEST(Direction, AFaceThatLooksDownIsRefusedAndWorkIsBounded) {
  TopoDS_Face under = BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), 0, 100, 0, 100).Face();
  under.Reverse();  // the underside of a block: its normal, out of the material, is −Z
  try {
    optimalDirection(under, case1(6000), paperMachine(), DirectionSettings{});
    FAIL() << "a face that looks down was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("looks down"), std::string::npos) << e.what();
  }
  const TopoDS_Face flat = BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), 0, 100, 0, 100).Face();
  for (const DirectionSettings& s : {DirectionSettings{100000, 100000, 1.0, 0.95}, DirectionSettings{1, 50, 1.0, 0.95},
                                     DirectionSettings{500, 500, 0.01, 0.95}, DirectionSettings{50, 50, 1e-9, 0.95}})
    EXPECT_THROW(optimalDirection(flat, case1(6000), paperMachine(), s), InputError) << s.gridU << " " << s.angleStepDeg;
}
