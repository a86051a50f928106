// Analytic boundaries for the curve-net tests.
#pragma once

#include "geometry/bspline.hpp"

#include <cmath>
#include <functional>

namespace hsm::test {

// B-spline through y = f(x), z = g(x, y) for x in [x0, x1] (dense enough that it is f within microns).
inline Handle(Geom_BSplineCurve) planCurve(double x0, double x1, const std::function<double(double)>& f,
                                           const std::function<double(double, double)>& z = {}, int n = 201) {
  geometry::PointArray points(n, 3);
  for (int i = 0; i < n; ++i) {
    const double x = x0 + (x1 - x0) * i / (n - 1), y = f(x);
    points.row(i) << x, y, z ? z(x, y) : 0.0;
  }
  return geometry::interpolatePoints(points);
}

inline Handle(Geom_BSplineCurve) line(double x0, double x1, double y) {
  return planCurve(x0, x1, [y](double) { return y; }, {}, 2);
}

// y of a curve at station x (the curve cut by the plane x = const).
double yAt(const Handle(Geom_BSplineCurve)& curve, double x);

}  // namespace hsm::test
