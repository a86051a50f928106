#include "common/error.hpp"
#include "geometry/bspline.hpp"
#include "geometry/plane_cutter.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeCircle.hxx>
#include <TopoDS_Compound.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <gtest/gtest.h>

#include <cmath>

using namespace hsm::geometry;

namespace {
TopoDS_Shape circleEdge(double radius) {
  return BRepBuilderAPI_MakeEdge(GC_MakeCircle(gp_Ax2(gp_Pnt(1, 2, 3), gp::DZ()), radius).Value()).Edge();
}
TopoDS_Shape segment(gp_Pnt a, gp_Pnt b) { return BRepBuilderAPI_MakeEdge(a, b).Edge(); }
}  // namespace

TEST(CurveSampling, CirclePointsLieOnTheCircleEquallySpaced) {
  const int count = 37;
  const PointArray points = sampleByArcLength(circleEdge(10.0), count);
  ASSERT_EQ(points.rows(), count);
  const double expectedChord = 2 * 10.0 * std::sin(M_PI / (count - 1));
  for (int i = 0; i < count; ++i) {
    EXPECT_NEAR(std::hypot(points(i, 0) - 1, points(i, 1) - 2), 10.0, 1e-9);
    EXPECT_NEAR(points(i, 2), 3.0, 1e-12);
    if (i > 0) {
      EXPECT_NEAR((points.row(i) - points.row(i - 1)).norm(), expectedChord, 1e-7);
    }
  }
  EXPECT_NEAR((points.row(0) - points.row(count - 1)).norm(), 0.0, 1e-9);  // closed curve
}

TEST(CurveSampling, UnorderedCompoundOfEdgesIsChained) {
  // An L-shaped chain given out of order: 10 mm along X then 5 mm along Y.
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  builder.Add(compound, segment(gp_Pnt(10, 0, 0), gp_Pnt(10, 5, 0)));
  builder.Add(compound, segment(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0)));
  const PointArray points = sampleByArcLength(compound, 4);  // spacing 5 mm along 15 mm
  const Eigen::RowVector3d first = points.row(0), last = points.row(3);
  const double endToEnd = (last - first).norm();
  EXPECT_NEAR(endToEnd, std::hypot(10.0, 5.0), 1e-9);
  EXPECT_NEAR(points(1, 1) + points(2, 1), 0.0, 1e-9);  // the two inner points lie on the X leg
}

TEST(CurveSampling, BadInputsAreRefused) {
  EXPECT_THROW(sampleByArcLength(circleEdge(5.0), 1), hsm::InputError);
  EXPECT_THROW(sampleByArcLength(TopoDS_Shape(), 5), hsm::InputError);
  EXPECT_THROW(sampleByArcLength(BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0)).Shape(), 5), hsm::InputError);

  BRep_Builder builder;
  TopoDS_Compound apart;
  builder.MakeCompound(apart);
  builder.Add(apart, segment(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)));
  builder.Add(apart, segment(gp_Pnt(5, 0, 0), gp_Pnt(6, 0, 0)));
  try {
    sampleByArcLength(apart, 5);
    FAIL() << "disconnected edges were accepted";
  } catch (const hsm::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("2 pieces"), std::string::npos) << error.what();
  }
}

namespace {
Handle(Geom_BSplineCurve) straightCurve(gp_Pnt a, gp_Pnt b) {
  TColgp_Array1OfPnt poles(1, 2);
  poles(1) = a;
  poles(2) = b;
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0.0;
  knots(2) = 1.0;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities(1) = multiplicities(2) = 2;
  return new Geom_BSplineCurve(poles, knots, multiplicities, 1);
}
}  // namespace

// A net's first plane lies at one boundary's end; a curve that ends a rounding error short of it (a boundary read
// back from a saved document) is cut at its end, while a plane clearly beyond the curve is an error naming both.
TEST(PlaneCutter, APlaneARoundingErrorBeyondTheEndCutsAtTheEnd) {
  const PlaneCutter cutter(straightCurve(gp_Pnt(1e-9, 0, 0), gp_Pnt(10, 5, 0)), Eigen::Vector3d::UnitX());
  const auto cuts = cutter.cut({-1e-9, 5.0, 10.0 + 1e-8});
  EXPECT_NEAR(cuts.points(0, 1), 0.0, 1e-6);
  EXPECT_NEAR(cuts.points(1, 1), 2.5, 1e-9);
  EXPECT_NEAR(cuts.points(2, 1), 5.0, 1e-6);
  try {
    cutter.cut({-0.001});
    FAIL() << "a plane 0.001 mm before the curve cut it";
  } catch (const hsm::ComputationError& error) {
    EXPECT_NE(std::string(error.what()).find("the plane at -0.001 mm"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("curve extent 1e-09..10 mm"), std::string::npos) << error.what();
  }
}
