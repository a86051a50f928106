// Where the planes d·x = s (stations along a direction d) cut a curve: the curve nets' construction planes
// and the guide-curve passes' stations both need it.
#pragma once

#include "geometry/points.hpp"

#include <Geom_BSplineCurve.hxx>

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace hsm::geometry {

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
  // One point per station with the continuation rule (the first cut at or after the previous one in the curve's order, else
  // the last). Stations must be increasing and
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

}  // namespace hsm::geometry
