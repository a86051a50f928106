// Curves as B-splines: the one representation the curve-net and toolpath code works on.
#pragma once

#include "geometry/points.hpp"
#include "geometry/wire.hpp"

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace hsm::geometry {

// Exact B-spline of an edge, a wire or a chain of edges (lines and circles become rational B-splines),
// in the chain's order. Throws InputError for a shape that is not a chain of edges of non-zero length.
Handle(Geom_BSplineCurve) toBSpline(const TopoDS_Shape& curve);

// Cubic B-spline through points given along a curve (chord-length parameters); consecutive duplicate
// points are dropped. Throws InputError when fewer than 2 distinct points remain or a value is not finite.
Handle(Geom_BSplineCurve) interpolatePoints(const PointArray& points);

// `count` points equally spaced by arc length along the curve, ends included.
PointArray sampleByArcLength(const Handle(Geom_Curve)& curve, int count);
// The same along a curve given as an edge, a wire or a chain of edges. Throws InputError when count < 2 or
// the curve is not a chain of edges of non-zero length.
PointArray sampleByArcLength(const TopoDS_Shape& curve, int count);

// BREP text of an edge on the curve (what FreeCAD's Part.Shape().importBrepFromString() reads).
std::string edgeBrep(const Handle(Geom_Curve)& curve);

// Curvature at one parameter: radius in 3D and signed curvature of the projection on the plane normal to
// `axis` (positive turning counter-clockwise seen from +axis).
struct CurvatureSample {
  double parameter = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double radius = 0.0;         // mm, infinity where straight
  double planCurvature = 0.0;  // 1/mm
};

CurvatureSample curvatureAt(const Handle(Geom_BSplineCurve)& curve, double parameter, const Eigen::Vector3d& axis);

// `samples` curvature samples at evenly spaced parameters, ends included.
std::vector<CurvatureSample> sampleCurvature(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& axis,
                                             int samples);

// Shape measures of a curve that guide the guidance-curve method (paper §4.3).
struct CurveShapeReport {
  double length = 0.0;            // mm
  double minRadius = 0.0;         // smallest radius of curvature in 3D, mm (infinity for a straight curve)
  double minRadiusParameter = 0.0;
  double minPlanRadius = 0.0;     // smallest radius of the projection on the plane normal to `axis`, mm
  std::vector<double> inflectionParameters;  // where the curvature seen along `axis` changes sign
  bool straight = false;          // every point within the tolerance of the chord
};

// Measures a curve by dense sampling (`samples` points) refined on each inflection. `axis` is the view
// direction of the plan (the tool axis, Z for 3-axis work); `straightTolerance` in mm. Turns with a plan
// radius above `inflectionRadius` mm count as straight, so that noise on a line is not called an inflection.
CurveShapeReport analyzeCurve(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& axis,
                              double straightTolerance = 0.01, double inflectionRadius = 1000.0,
                              int samples = 2000);

}  // namespace hsm::geometry
