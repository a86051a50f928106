// Safe links between the sweeps of several regions (sweep.hpp: joinSweeps).
#include "roughing/sweep.hpp"
#include "geometry/bounds.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <Bnd_Box.hxx>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hsm::roughing {

namespace {

struct Sphere {
  Eigen::Vector3d centre;
  double radius;
};

// Where the line p + t·axis (t ≥ 0) leaves the sphere (p inside it or not: the far crossing).
Eigen::Vector3d outAlong(const Sphere& s, const Eigen::Vector3d& p, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d w = p - s.centre;
  const double half = w.dot(axis), c = w.squaredNorm() - s.radius * s.radius;
  const double t = -half + std::sqrt(std::max(0.0, half * half - c));
  return p + std::max(0.0, t) * axis;
}

void add(std::vector<ToolMove>& out, const Eigen::Vector3d& tip, const Eigen::Vector3d& axis) {
  ToolMove m;
  m.kind = MoveKind::Rapid;
  m.tip = tip;
  m.axis = axis.normalized();
  m.subVolume = -1;
  out.push_back(m);
}

// The axis turned from `from` to `to` about the tip, in steps of at most 5°.
void turn(std::vector<ToolMove>& out, const Eigen::Vector3d& tip, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const double angle = std::acos(std::clamp(from.dot(to), -1.0, 1.0));
  const int steps = std::max(1, static_cast<int>(std::ceil(angle / (5.0 * M_PI / 180.0))));
  for (int k = 1; k <= steps; ++k) {
    const double f = double(k) / steps;
    add(out, tip, ((1.0 - f) * from + f * to).normalized());
  }
}

void linkOnSphere(std::vector<ToolMove>& out, const Sphere& s, const ToolMove& a, const ToolMove& b, double clearance) {
  const Eigen::Vector3d p1 = outAlong(s, a.tip, a.axis.normalized()), p2 = outAlong(s, b.tip, b.axis.normalized());
  add(out, p1, a.axis);
  const Eigen::Vector3d r1 = (p1 - s.centre).normalized(), r2 = (p2 - s.centre).normalized();
  turn(out, p1, a.axis.normalized(), r1);
  // Along the great circle (the plane through r1 and r2; any plane through r1 when they are opposite).
  const double angle = std::acos(std::clamp(r1.dot(r2), -1.0, 1.0));
  Eigen::Vector3d across = r2 - r1.dot(r2) * r1;
  if (!(across.norm() > 1e-9)) across = r1.unitOrthogonal();
  across.normalize();
  const double chord = 2.0 * std::acos(std::max(-1.0, 1.0 - 0.5 * clearance / s.radius));
  const int steps = std::max(1, static_cast<int>(std::ceil(angle / std::max(chord, 1e-3))));
  for (int k = 1; k <= steps; ++k) {
    const double phi = angle * k / steps;
    const Eigen::Vector3d r = std::cos(phi) * r1 + std::sin(phi) * across;
    add(out, s.centre + s.radius * r, r);
  }
  turn(out, p2, r2, b.axis.normalized());  // the next region's first move goes in along its axis
}

}  // namespace

std::vector<ToolMove> joinSweeps(const std::vector<std::vector<ToolMove>>& regions, const TopoDS_Shape& stock,
                                 double clearance) {
  if (!(clearance >= 0.0 && clearance <= 1000.0))
    throw InputError("clearance " + number(clearance) + " mm is outside [0, 1000] mm (default 5)");
  std::vector<ToolMove> out;
  bool oneAxis = true;
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  for (const auto& moves : regions)
    for (const ToolMove& m : moves) {
      if (axis.isZero()) axis = m.axis.normalized();
      oneAxis = oneAxis && m.axis.normalized().dot(axis) > 1.0 - 1e-12;
    }
  Bnd_Box box = geometry::exactBounds(stock);
  if (box.IsVoid()) throw InputError("joining sweeps: the stock is empty");
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const Sphere sphere{{0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)},
                      0.5 * std::hypot(x1 - x0, y1 - y0, z1 - z0) + clearance};
  // One axis: a plane normal to it, `clearance` above the stock's highest corner.
  double top = -1e300;
  for (double x : {x0, x1})
    for (double y : {y0, y1})
      for (double z : {z0, z1}) top = std::max(top, axis.dot(Eigen::Vector3d(x, y, z)));
  const double safe = top + clearance;
  for (const auto& moves : regions) {
    if (moves.empty()) continue;
    if (!out.empty()) {
      const ToolMove a = out.back(), b = moves.front();
      if (oneAxis) {
        add(out, a.tip + (safe - axis.dot(a.tip)) * axis, axis);
        add(out, b.tip + (safe - axis.dot(b.tip)) * axis, axis);
      } else {
        linkOnSphere(out, sphere, a, b, clearance);
      }
    }
    out.insert(out.end(), moves.begin(), moves.end());
  }
  return out;
}

}  // namespace hsm::roughing
