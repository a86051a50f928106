#include "common/error.hpp"
#include "curvenet/curvenet.hpp"
#include "curves.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <gtest/gtest.h>

#include <cmath>

using namespace hsm;
using namespace hsm::curvenet;
using hsm::test::line;
using hsm::test::planCurve;
using hsm::test::yAt;

namespace {
double wave(double x) { return 5.0 * std::sin(2.0 * M_PI * x / 100.0); }
}  // namespace

TEST(IntermediateCurve, ParallelLinesGiveTheLineAtRatioKFromTheStart) {
  NetSettings settings;
  settings.step = 5.0;
  const NetCurve c = intermediateCurve(line(0, 100, 0), line(0, 100, 10), 0.3, settings);
  EXPECT_EQ(c.curve->Degree(), 5);
  EXPECT_EQ(c.points.rows(), 21);  // 100 mm at 5 mm, both ends
  for (double x : {0.0, 12.5, 50.0, 77.7, 100.0}) EXPECT_NEAR(yAt(c.curve, x), 3.0, 1e-6) << x;
  EXPECT_LT(c.fitDeviation, settings.fitTolerance);
}

TEST(IntermediateCurve, PointsFollowEquationOneInEveryPlane) {
  // Pint = Pa + K (Pb − Pa) measured from Ca: with Ca a sine and Cb the line y = 30.
  NetSettings settings;
  settings.step = 2.0;
  const double k = 0.25;
  const NetCurve c = intermediateCurve(planCurve(0, 100, wave), line(0, 100, 30), k, settings);
  ASSERT_EQ(c.points.rows(), 51);
  for (Eigen::Index i = 0; i < c.points.rows(); ++i) {
    const double x = c.points(i, 0);
    EXPECT_NEAR(x, 2.0 * i, 1e-9);
    EXPECT_NEAR(c.points(i, 1), wave(x) + k * (30.0 - wave(x)), 1e-6);
  }
  // Between the planes the curve stays within the fit tolerance of the analytic intermediate curve.
  for (double x = 1.0; x < 100.0; x += 2.0)
    EXPECT_NEAR(yAt(c.curve, x), wave(x) + k * (30.0 - wave(x)), 0.02) << x;
}

TEST(IntermediateCurve, ReversedInputsGiveTheSameCurveOrientedAlongTheDirection) {
  NetSettings settings;
  Handle(Geom_BSplineCurve) a = planCurve(0, 100, wave);
  Handle(Geom_BSplineCurve) reversed = Handle(Geom_BSplineCurve)::DownCast(a->Reversed());
  const NetCurve c1 = intermediateCurve(a, line(0, 100, 30), 0.5, settings);
  const NetCurve c2 = intermediateCurve(reversed, line(0, 100, 30), 0.5, settings);
  EXPECT_LT((c1.points - c2.points).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(c1.curve->StartPoint().X(), c1.curve->EndPoint().X());
}

TEST(IntermediateCurve, GivenDirectionSetsThePlanes) {
  // Boundaries along Y; planes perpendicular to Y.
  NetSettings settings;
  settings.direction = Eigen::Vector3d::UnitY();
  geometry::PointArray a(2, 3), b(2, 3);
  a << 0, 0, 0, 0, 50, 0;
  b << 20, 0, 0, 20, 50, 0;
  const NetCurve c = intermediateCurve(geometry::interpolatePoints(a), geometry::interpolatePoints(b), 0.5, settings);
  EXPECT_NEAR(c.points(0, 1), 0.0, 1e-9);
  EXPECT_NEAR(c.points(c.points.rows() - 1, 1), 50.0, 1e-9);
  EXPECT_NEAR(c.points(3, 0), 10.0, 1e-9);
}

TEST(IntermediateCurve, PointsAreDroppedOnTheBottomFaceAlongTheToolAxis) {
  // Bottom: the lower half of a cylinder of radius 50 about the X axis, lowest line z = 0.
  Handle(Geom_CylindricalSurface) cylinder =
      new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(0, 0, 50), gp::DX(), gp::DZ()), 50.0);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(cylinder, 0.5 * M_PI, 1.5 * M_PI, -10, 110, 1e-7).Face();
  auto onCylinder = [](double, double y) { return 50.0 - std::sqrt(2500.0 - y * y); };
  NetSettings settings;
  settings.face = face;
  const auto b1 = planCurve(0, 100, [](double) { return -20.0; }, onCylinder, 3);
  const auto b2 = planCurve(0, 100, [](double) { return 20.0; }, onCylinder, 3);
  const NetCurve c = intermediateCurve(b1, b2, 0.5, settings);
  for (Eigen::Index i = 0; i < c.points.rows(); ++i) {
    EXPECT_NEAR(c.points(i, 1), 0.0, 1e-9);  // the plan position of eq. 1 is kept
    EXPECT_NEAR(c.points(i, 2), 0.0, 1e-7);  // on the face, not on the chord (z = 4.17)
  }
  const NetCurve quarter = intermediateCurve(b1, b2, 0.25, settings);
  EXPECT_NEAR(quarter.points(0, 2), onCylinder(0, -10.0), 1e-7);
}

TEST(IntermediateCurve, FewPlanesLowerTheDegreeWithAWarningAndLongStepsAreRefused) {
  NetSettings settings;
  settings.step = 40.0;  // 100 mm: 4 planes
  Boundaries boundaries{line(0, 100, 0), line(0, 100, 10)};
  const CurveNet net = curveNet(boundaries, 0.5, NetMode::Median, settings);
  EXPECT_EQ(net.curves[1].curve->Degree(), 3);
  ASSERT_FALSE(net.warnings.empty());
  EXPECT_NE(net.warnings.back().find("degree 3 instead of 5"), std::string::npos);
  settings.step = 120.0;
  try {
    intermediateCurve(line(0, 100, 0), line(0, 100, 10), 0.5, settings);
    FAIL() << "a step longer than the part was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("longer than the common extent"), std::string::npos) << error.what();
  }
}

TEST(IntermediateCurve, RatioOutsideTheOpenIntervalIsRefused) {
  NetSettings settings;
  for (double k : {0.0, 1.0, -0.2, 1.5, std::nan("")}) {
    try {
      intermediateCurve(line(0, 100, 0), line(0, 100, 10), k, settings);
      FAIL() << "K = " << k << " was accepted";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("outside ]0,1["), std::string::npos) << error.what();
    }
  }
}

TEST(IntermediateCurve, BadStepsAndDirectionsAreRefused) {
  NetSettings settings;
  for (double step : {0.0, -5.0, std::nan("")}) {
    settings.step = step;
    EXPECT_THROW(intermediateCurve(line(0, 100, 0), line(0, 100, 10), 0.5, settings), InputError) << step;
  }
  settings.step = 5.0;
  settings.direction = Eigen::Vector3d::UnitZ();
  EXPECT_THROW(intermediateCurve(line(0, 100, 0), line(0, 100, 10), 0.5, settings), InputError);
  settings.direction = Eigen::Vector3d::Zero();
  EXPECT_THROW(intermediateCurve(line(0, 100, 0), line(0, 100, 10), 0.5, settings), InputError);
}
