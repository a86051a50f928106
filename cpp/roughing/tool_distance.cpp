#include "roughing/tool_distance.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hsm::roughing {

namespace {
// Plan distance (across the axis) from the axis point to a convex polygon of the plane: 0 when it contains it.
// A polygon seen edge-on (a wall along the axis) has no inside: only its edges count.
double planDistance(const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.empty()) return std::numeric_limits<double>::infinity();
  double best = std::numeric_limits<double>::infinity(), area = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const Eigen::Vector2d d = b - a;
    const double t = d.squaredNorm() > 0.0 ? std::clamp(-a.dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * d).norm());
    area += a.x() * b.y() - a.y() * b.x();
  }
  if (!(std::abs(area) > 1e-9) || best == 0.0) return best;
  const double orientation = area > 0.0 ? 1.0 : -1.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d d = polygon[(i + 1) % polygon.size()] - a;
    if (orientation * (d.x() * (-a.y()) - d.y() * (-a.x())) < 0.0) return best;  // the origin is outside
  }
  return 0.0;
}

// The triangle (tool frame: x, y across the axis, z = height above the tip) clipped to lo ≤ z ≤ hi.
std::vector<Eigen::Vector3d> clipSlab(const std::vector<Eigen::Vector3d>& polygon, double lo, double hi) {
  auto clip = [](const std::vector<Eigen::Vector3d>& in, double level, bool keepAbove) {
    std::vector<Eigen::Vector3d> out;
    for (size_t i = 0; i < in.size(); ++i) {
      const Eigen::Vector3d& a = in[i];
      const Eigen::Vector3d& b = in[(i + 1) % in.size()];
      const bool ka = keepAbove ? a.z() >= level : a.z() <= level, kb = keepAbove ? b.z() >= level : b.z() <= level;
      if (ka) out.push_back(a);
      if (ka != kb) out.push_back(a + (b - a) * ((level - a.z()) / (b.z() - a.z())));
    }
    return out;
  };
  return clip(clip(polygon, lo, true), hi, false);
}

std::vector<Eigen::Vector2d> plan(const std::vector<Eigen::Vector3d>& polygon) {
  std::vector<Eigen::Vector2d> out;
  for (const Eigen::Vector3d& p : polygon) out.emplace_back(p.x(), p.y());
  return out;
}

// Distance from a point to the tool's bottom disk (radius r, at z = 0, centre on the axis). Square roots, not
// hypot: millimetre coordinates neither overflow nor underflow, and the check calls this millions of times.
double toDisk(const Eigen::Vector3d& p, double r) {
  const double across = std::max(0.0, std::sqrt(p.x() * p.x() + p.y() * p.y()) - r);
  return std::sqrt(across * across + p.z() * p.z());
}

// Distance from a convex polygon under the tip (z ≤ 0) to the bottom disk: a convex function over a convex
// set, so its least value is where the plane's nearest point to the disk falls, if that is inside the polygon,
// else on an edge (each searched by ternary search: convex along it).
double diskDistance(const std::vector<Eigen::Vector3d>& polygon, double r) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % polygon.size()];
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 40; ++k) {
      const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
      if (toDisk(a + (b - a) * m1, r) <= toDisk(a + (b - a) * m2, r)) hi = m2;
      else lo = m1;
    }
    best = std::min({best, toDisk(a, r), toDisk(a + (b - a) * (0.5 * (lo + hi)), r)});
  }
  if (polygon.size() < 3) return best;
  Eigen::Vector3d n = (polygon[1] - polygon[0]).cross(polygon[2] - polygon[0]);
  if (!(n.norm() > 1e-12)) return best;
  n.normalize();
  if (n.z() < 0.0) n = -n;  // towards the disk's side
  // The disk's point nearest the plane: its rim point against the plane's slope (the centre if level), and
  // that point's projection on the plane.
  const Eigen::Vector2d slope(n.x(), n.y());
  const Eigen::Vector3d rim = slope.norm() > 1e-12 ? Eigen::Vector3d(-r * slope.x() / slope.norm(), -r * slope.y() / slope.norm(), 0.0)
                                                   : Eigen::Vector3d::Zero();
  const Eigen::Vector3d foot = rim - n * n.dot(rim - polygon[0]);
  std::vector<Eigen::Vector2d> shifted;  // is the foot inside the polygon? (plan test around the foot)
  const Eigen::Vector3d e1 = (polygon[1] - polygon[0]).normalized(), e2 = n.cross(e1);
  for (const Eigen::Vector3d& p : polygon) shifted.emplace_back(e1.dot(p - foot), e2.dot(p - foot));
  if (planDistance(shifted) == 0.0) best = std::min(best, toDisk(foot, r));
  return best;
}

// Distance from the core (a cylinder of radius r over 0 ≤ z ≤ length) to a polygon given in its frame.
double coreDistance(const std::vector<Eigen::Vector3d>& triangle, double r, double length) {
  double best = std::numeric_limits<double>::infinity();
  const std::vector<Eigen::Vector3d> slab = clipSlab(triangle, 0.0, length);
  if (!slab.empty()) best = std::max(0.0, planDistance(plan(slab)) - r);
  const std::vector<Eigen::Vector3d> below = clipSlab(triangle, -1e300, 0.0);
  if (!below.empty()) best = std::min(best, diskDistance(below, r));
  return best;
}

}  // namespace

CutterBody::CutterBody(const Cutter& cutter, double length)
    : coreRadius(cutter.radius() - cutter.corner()), corner(cutter.corner()), length(length) {}

double cutterDistance(const Eigen::Vector3d (&triangle)[3], const CutterBody& body, double lowest) {
  // From the core's bottom, r above the tip.
  std::vector<Eigen::Vector3d> polygon;
  for (const Eigen::Vector3d& p : triangle) polygon.emplace_back(p.x(), p.y(), p.z() - body.corner);
  if (lowest > -std::numeric_limits<double>::infinity()) {
    polygon = clipSlab(polygon, lowest - body.corner, std::numeric_limits<double>::max());
    if (polygon.empty()) return std::numeric_limits<double>::infinity();
  }
  return coreDistance(polygon, body.coreRadius, body.length - body.corner) - body.corner;
}

}  // namespace hsm::roughing
