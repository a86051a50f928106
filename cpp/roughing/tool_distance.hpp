// The exact distance from a cutter to a triangle of the part (internal to the roughing): what the clearance
// check measures along a toolpath and what the sweep pushes a level's domain out by.
//
// A torus end mill (a ball, a flat end) is the Minkowski sum of its core — a cylinder of radius R − r from r
// above the tip — and a ball of its corner radius r, so its distance to a triangle is the core's less r,
// exactly. The distance from the core to a triangle: the triangle is cut at the core's bottom plane and at the
// top of the length looked at; the part between is as far as its plan distance to the axis less the core's
// radius; the part below as far as its nearest point to the core's bottom disk (a convex problem: the plane's
// foot if inside the polygon, else along its edges).
#pragma once

#include "roughing/sweep.hpp"

#include <Eigen/Core>

#include <limits>

namespace hsm::roughing {

// The cutter up its axis from the tip over `length` mm (the stick-out: the holder above is another check).
struct CutterBody {
  CutterBody(const Cutter& cutter, double length);
  double coreRadius, corner, length;
};

// The distance from the cutter to a triangle whose corners are given in the tool's frame: x, y across the
// axis, z the height above the tip. The triangle's part lower than `lowest` (height above the tip) is left out:
// a floor the level stands the allowance over, on purpose. 0 where they meet.
double cutterDistance(const Eigen::Vector3d (&triangle)[3], const CutterBody& body,
                      double lowest = -std::numeric_limits<double>::infinity());

}  // namespace hsm::roughing
