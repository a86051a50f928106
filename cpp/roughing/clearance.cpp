#include "roughing/clearance.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/triangle_grid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {
constexpr long kMaxPositions = 2000000;  // about 1 ms each on the impeller: bounded work

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

// Distance from the tool (cylinder of radius r over 0 ≤ z ≤ length) to a triangle given in the tool's frame:
// exact below the stick-out; the part above it left out (the holder's check).
double toolDistance(const std::vector<Eigen::Vector3d>& triangle, double r, double length) {
  double best = std::numeric_limits<double>::infinity();
  const std::vector<Eigen::Vector3d> slab = clipSlab(triangle, 0.0, length);
  if (!slab.empty()) best = std::max(0.0, planDistance(plan(slab)) - r);
  const std::vector<Eigen::Vector3d> below = clipSlab(triangle, -1e300, 0.0);
  if (!below.empty()) best = std::min(best, diskDistance(below, r));
  return best;
}
}  // namespace

struct ClearanceChecker::Impl {
  Impl(const TopoDS_Shape& part, double deflection)
      : deflection(deflection), mesh(geometry::meshFaces(part, deflection)), grid(mesh, kCell) {}
  static constexpr double kCell = 4.0;  // mm: the grid's cubes
  double deflection;
  geometry::TriangleMesh mesh;
  TriangleGrid grid;
};

ClearanceChecker::ClearanceChecker(const TopoDS_Shape& part, double deflection) {
  if (!(deflection >= 0.001 && deflection <= 1.0))
    throw InputError("clearance check: deflection " + number(deflection) + " mm is outside [0.001, 1] mm");
  impl_ = std::make_unique<Impl>(part, deflection);
}

ClearanceChecker::~ClearanceChecker() = default;

ClearanceReport ClearanceChecker::check(const std::vector<ToolMove>& moves, const Cutter& cutter, double limit,
                                        double spacing) const {
  checkCutter(cutter);
  if (!(spacing >= 0.01 && spacing <= 100.0))
    throw InputError("clearance check: spacing " + number(spacing) + " mm is outside [0.01, 100] mm");
  long total = static_cast<long>(moves.size());
  // Samples of a move: every `spacing` mm of the tip's path or of the holder's end's, whichever is more (a
  // 5-axis move turns the axis as it goes).
  auto samplesOf = [&](size_t i) {
    const double turn = std::acos(std::clamp(moves[i].axis.normalized().dot(moves[i - 1].axis.normalized()), -1.0, 1.0));
    return 1 + static_cast<long>(std::max((moves[i].tip - moves[i - 1].tip).norm(), turn * cutter.stickOut) / spacing);
  };
  for (size_t i = 1; i < moves.size(); ++i) {
    total += samplesOf(i) - 1;
    if (total > kMaxPositions)
      throw InputError("clearance check: more than " + std::to_string(kMaxPositions) + " positions at " + number(spacing) +
                       " mm: use a larger spacing");
  }
  const geometry::TriangleMesh& mesh = impl_->mesh;
  const double deflection = impl_->deflection;
  // The cutter is its core — a cylinder of radius R − r standing r above the tip, up to the stick-out — grown
  // by a ball of its corner radius r (a torus end mill; a ball for r = R, a flat end for r = 0): the distance
  // to it is the distance to the core less r, exactly.
  const double corner = cutter.corner(), r = cutter.radius() - corner, length = cutter.stickOut - corner;
  const double reach = std::max(limit, 0.0) + 2.0;  // triangles farther than this from the tool do not matter
  std::vector<int> seen(mesh.triangles.size(), -1);
  int stamp = 0;
  ClearanceReport report;
  report.minimum = std::numeric_limits<double>::infinity();
  report.moveMinimum.assign(moves.size(), reach);
  std::vector<Eigen::Vector3d> local(3);
  auto checkAt = [&](const Eigen::Vector3d& tip, const Eigen::Vector3d& axis, int move) {
    const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
    double least = reach;
    impl_->grid.near(tip - axis * reach, tip + axis * cutter.stickOut, cutter.radius() + reach, seen, stamp++, [&](int t) {
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d d = mesh.vertices[mesh.triangles[t][k]] - tip;
        local[k] = Eigen::Vector3d(u.dot(d), v.dot(d), axis.dot(d) - corner);  // from the core's bottom
      }
      // Quick rejections: wholly above the stick-out, or farther across than the reach.
      if (std::min({local[0].z(), local[1].z(), local[2].z()}) > length) return;
      if (std::max({local[0].z(), local[1].z(), local[2].z()}) < -least - corner) return;
      least = std::min(least, toolDistance(local, r, length) - corner);
    });
    least -= deflection;
    report.moveMinimum[move] = std::min(report.moveMinimum[move], least);
    ++report.positions;
    if (least < limit) ++report.tooClose;
    if (least < report.minimum) {
      report.minimum = least;
      report.worstMove = move;
      report.worstTip = tip;
    }
  };
  // Along a move the tip goes straight and the axis turns evenly between its ends (as a controller's
  // orientation interpolation does between the ends' vectors).
  for (size_t i = 0; i < moves.size(); ++i) {
    const Eigen::Vector3d from = i > 0 ? moves[i - 1].tip : moves[i].tip;
    const Eigen::Vector3d fromAxis = i > 0 ? moves[i - 1].axis.normalized() : moves[i].axis.normalized();
    const long samples = i > 0 ? samplesOf(i) : 1;
    for (long k = 1; k <= samples; ++k) {
      const double f = double(k) / double(samples);
      const Eigen::Vector3d axis = ((1.0 - f) * fromAxis + f * moves[i].axis.normalized()).normalized();
      checkAt(from + (moves[i].tip - from) * f, axis, static_cast<int>(i));
    }
  }
  return report;
}

ClearanceReport checkClearance(const std::vector<ToolMove>& moves, const TopoDS_Shape& part, const Cutter& cutter,
                               double limit, double spacing, double deflection) {
  return ClearanceChecker(part, deflection).check(moves, cutter, limit, spacing);
}

}  // namespace hsm::roughing
