#include "geometry/bspline.hpp"

#include "common/error.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_CompCurveToBSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopoDS.hxx>

#include "geometry/brep.hpp"

#include <cmath>
#include <limits>

namespace hsm::geometry {

namespace {
constexpr double kJoinTolerance = 1e-4;  // mm: edges of a chain closer than this are joined
constexpr double kMinLength = 1e-6;      // mm

Handle(Geom_BSplineCurve) edgeToBSpline(const TopoDS_Edge& edge) {
  double first = 0.0, last = 0.0;
  Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
  if (curve.IsNull()) throw InputError("an edge of the curve has no 3D geometry (a degenerated edge): remove it");
  if (std::abs(last - first) < Precision::PConfusion())
    throw InputError("an edge of the curve has zero length: remove it or pass a longer edge");
  Handle(Geom_TrimmedCurve) trimmed = new Geom_TrimmedCurve(curve, first, last);
  Handle(Geom_BSplineCurve) spline = GeomConvert::CurveToBSplineCurve(trimmed);
  if (edge.Orientation() == TopAbs_REVERSED) spline->Reverse();
  return spline;
}
}  // namespace

Handle(Geom_BSplineCurve) toBSpline(const TopoDS_Shape& shape) {
  const TopoDS_Wire wire = toWire(shape);
  try {
    GeomConvert_CompCurveToBSplineCurve joiner;
    int count = 0;
    for (BRepTools_WireExplorer it(wire); it.More(); it.Next(), ++count) {
      if (!joiner.Add(edgeToBSpline(it.Current()), kJoinTolerance, /*After=*/true))
        throw InputError("edge " + std::to_string(count + 1) + " of the curve does not continue the previous one: "
                         "pass edges that meet end to end");
    }
    Handle(Geom_BSplineCurve) spline = joiner.BSplineCurve();
    if (count == 0 || spline.IsNull()) throw InputError("the curve has no usable edge: pass an edge or a wire");
    if (GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(spline)) < kMinLength)
      throw InputError("the curve has zero length: pass an edge or wire with distinct end points");
    return spline;
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("the curve could not be converted to a B-spline (") + failure.GetMessageString() +
                     "): pass a chain of ordinary edges");
  }
}

Handle(Geom_BSplineCurve) interpolatePoints(const PointArray& points) {
  std::vector<gp_Pnt> distinct;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (!points.row(i).allFinite())
      throw InputError("point " + std::to_string(i) + " of the curve is not finite: pass real coordinates in mm");
    const gp_Pnt p(points(i, 0), points(i, 1), points(i, 2));
    if (distinct.empty() || distinct.back().Distance(p) > kJoinTolerance) distinct.push_back(p);
  }
  if (distinct.size() < 2)
    throw InputError("the curve has " + std::to_string(distinct.size()) +
                     " distinct point(s): pass an (N,3) array of at least 2 distinct points along the curve");
  Handle(TColgp_HArray1OfPnt) array = new TColgp_HArray1OfPnt(1, static_cast<int>(distinct.size()));
  for (size_t i = 0; i < distinct.size(); ++i) array->SetValue(static_cast<int>(i) + 1, distinct[i]);
  try {
    GeomAPI_Interpolate interpolate(array, /*PeriodicFlag=*/false, kJoinTolerance);
    interpolate.Perform();
    if (!interpolate.IsDone()) throw InputError("no B-spline passes through the curve points: check their order");
    return interpolate.Curve();
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("no B-spline passes through the curve points (") + failure.GetMessageString() + ")");
  }
}

PointArray sampleByArcLength(const Handle(Geom_Curve)& curve, int count) {
  if (count < 2 || count > 1000000)
    throw InputError("sample count is " + std::to_string(count) + ": ask for 2 to 1,000,000 points");
  GeomAdaptor_Curve adaptor(curve);
  GCPnts_UniformAbscissa uniform(adaptor, count);
  if (!uniform.IsDone() || uniform.NbPoints() != count)
    throw ComputationError("OCCT could not place " + std::to_string(count) + " equally spaced points on the curve");
  PointArray points(count, 3);
  for (int i = 0; i < count; ++i) {
    const gp_Pnt p = curve->Value(uniform.Parameter(i + 1));
    points.row(i) << p.X(), p.Y(), p.Z();
  }
  return points;
}

std::string edgeBrep(const Handle(Geom_Curve)& curve) { return writeBrep(BRepBuilderAPI_MakeEdge(curve).Edge()); }

CurvatureSample curvatureAt(const Handle(Geom_BSplineCurve)& curve, double t, const Eigen::Vector3d& axis) {
  gp_Pnt p;
  gp_Vec d1, d2;
  curve->D2(t, p, d1, d2);
  const Eigen::Vector3d v(d1.X(), d1.Y(), d1.Z()), a(d2.X(), d2.Y(), d2.Z());
  const double speed = v.norm();
  CurvatureSample sample{t, Eigen::Vector3d(p.X(), p.Y(), p.Z()), std::numeric_limits<double>::infinity(), 0.0};
  if (speed < 1e-12) return sample;
  const double kappa = v.cross(a).norm() / (speed * speed * speed);
  if (kappa > 1e-12) sample.radius = 1.0 / kappa;
  const Eigen::Vector3d vp = v - axis.dot(v) * axis;  // plan projection
  const Eigen::Vector3d ap = a - axis.dot(a) * axis;
  const double planSpeed = vp.norm();
  if (planSpeed > 1e-12) sample.planCurvature = axis.dot(vp.cross(ap)) / (planSpeed * planSpeed * planSpeed);
  return sample;
}

std::vector<CurvatureSample> sampleCurvature(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& axisIn,
                                             int samples) {
  if (samples < 2) throw InputError("curvature sampling needs at least 2 samples, got " + std::to_string(samples));
  const Eigen::Vector3d axis = axisIn.normalized();
  const double t0 = curve->FirstParameter(), t1 = curve->LastParameter();
  std::vector<CurvatureSample> result;
  result.reserve(samples);
  for (int i = 0; i < samples; ++i) result.push_back(curvatureAt(curve, t0 + (t1 - t0) * i / (samples - 1), axis));
  return result;
}

namespace {
Eigen::Vector3d curveStart(const Handle(Geom_BSplineCurve)& c) {
  const gp_Pnt p = c->StartPoint();
  return {p.X(), p.Y(), p.Z()};
}
Eigen::Vector3d curveEnd(const Handle(Geom_BSplineCurve)& c) {
  const gp_Pnt p = c->EndPoint();
  return {p.X(), p.Y(), p.Z()};
}

// Parameter where the signed plan curvature crosses zero between t0 and t1 (bisection).
double refineInflection(const Handle(Geom_BSplineCurve)& curve, double t0, double t1, const Eigen::Vector3d& axis) {
  double k0 = curvatureAt(curve, t0, axis).planCurvature;
  for (int i = 0; i < 50 && t1 - t0 > 1e-12; ++i) {
    const double tm = 0.5 * (t0 + t1);
    const double km = curvatureAt(curve, tm, axis).planCurvature;
    if ((km < 0) == (k0 < 0)) {
      t0 = tm;
      k0 = km;
    } else {
      t1 = tm;
    }
  }
  return 0.5 * (t0 + t1);
}
}  // namespace

CurveShapeReport analyzeCurve(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& axisIn,
                              double straightTolerance, double inflectionRadius, int samples) {
  if (samples < 10) throw InputError("curve analysis needs at least 10 samples, got " + std::to_string(samples));
  const Eigen::Vector3d axis = axisIn.normalized();
  CurveShapeReport report;
  report.length = GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(curve));
  report.minRadius = report.minPlanRadius = std::numeric_limits<double>::infinity();

  const Eigen::Vector3d start = curveStart(curve);
  const Eigen::Vector3d chord = curveEnd(curve) - start;
  double maxChordDeviation = 0.0;
  const double significant = 1.0 / inflectionRadius;
  int lastSign = 0;
  double lastSignificantT = curve->FirstParameter();
  for (const CurvatureSample& c : sampleCurvature(curve, axis, samples)) {
    if (c.radius < report.minRadius) {
      report.minRadius = c.radius;
      report.minRadiusParameter = c.parameter;
    }
    if (c.planCurvature != 0.0) report.minPlanRadius = std::min(report.minPlanRadius, 1.0 / std::abs(c.planCurvature));
    const Eigen::Vector3d toPoint = c.point - start;
    const double deviation = chord.norm() > 1e-12 ? toPoint.cross(chord).norm() / chord.norm() : toPoint.norm();
    maxChordDeviation = std::max(maxChordDeviation, deviation);
    if (std::abs(c.planCurvature) >= significant) {
      const int sign = c.planCurvature > 0 ? 1 : -1;
      if (lastSign != 0 && sign != lastSign)
        report.inflectionParameters.push_back(refineInflection(curve, lastSignificantT, c.parameter, axis));
      lastSign = sign;
      lastSignificantT = c.parameter;
    }
  }
  report.straight = maxChordDeviation <= straightTolerance;
  if (report.straight) report.inflectionParameters.clear();
  return report;
}

PointArray sampleByArcLength(const TopoDS_Shape& curve, int count) {
  return sampleByArcLength(Handle(Geom_Curve)(toBSpline(curve)), count);
}

}  // namespace hsm::geometry
