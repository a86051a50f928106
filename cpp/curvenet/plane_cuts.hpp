// Internal pieces of the curve-net construction: cutting curves by the planes of the stations, dropping
// points on the bottom face along the tool axis, fitting the degree-5 curve.
#pragma once

#include "curvenet/curvenet.hpp"

#include <utility>
#include <vector>

namespace hsm::curvenet::detail {

// The machining direction d, the tool axis and the transverse direction t = axis × d that orders the
// curves across the feature (B1 on the low side).
struct Frame {
  Eigen::Vector3d direction, axis, transverse;
};

// Where the planes d·x = s cut one curve. The curve is oriented along +d; a dense table of s(t) brackets
// the cuts, Newton with a bisection guard refines them to 1e-9 mm.
class PlaneCutter {
public:
  PlaneCutter(Handle(Geom_BSplineCurve) curve, const Eigen::Vector3d& direction);

  const Handle(Geom_BSplineCurve)& curve() const { return curve_; }
  std::pair<double, double> extent() const { return {sMin_, sMax_}; }

  struct Cuts {
    PointArray points;                 // one per station
    std::vector<int> multiCutStations; // stations that cut the curve more than once
  };
  // One point per station with the continuation rule (see curvenet.hpp). Stations must be increasing and
  // lie in extent().
  Cuts cut(const std::vector<double>& stations) const;

private:
  double station(double t) const;
  double refine(double ta, double tb, double s) const;

  Handle(Geom_BSplineCurve) curve_;
  Eigen::Vector3d direction_;
  std::vector<double> t_, s_;
  double sMin_ = 0.0, sMax_ = 0.0;
};

// Copy of `curve` oriented so that d·x grows from its first to its last point.
Handle(Geom_BSplineCurve) orientedAlong(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& direction);

// Degree-5 (or points−1) B-spline approximating the points within `tolerance`, chord-length parameters, C2.
// Also returns the largest distance from a point to the curve.
std::pair<Handle(Geom_BSplineCurve), double> fitCurve(const PointArray& points, double tolerance);

}  // namespace hsm::curvenet::detail
