// Internal pieces of the curve-net construction: the frame of the machining direction and the fit of the
// degree-5 curve (the planes that cut the curves: geometry/plane_cutter.hpp).
#pragma once

#include "curvenet/curvenet.hpp"
#include "geometry/plane_cutter.hpp"

#include <utility>
#include <vector>

namespace hsm::curvenet::detail {

using geometry::orientedAlong;
using geometry::PlaneCutter;

// The machining direction d, the tool axis and the transverse direction t = axis × d that orders the
// curves across the feature (B1 on the low side).
struct Frame {
  Eigen::Vector3d direction, axis, transverse;
};

// Degree-5 (or points−1) B-spline approximating the points within `tolerance`, chord-length parameters, C2.
// Also returns the largest distance from a point to the curve.
std::pair<Handle(Geom_BSplineCurve), double> fitCurve(const PointArray& points, double tolerance);

}  // namespace hsm::curvenet::detail
