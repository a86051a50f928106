#include "toolpath/cusp.hpp"

#include <Geom_Surface.hxx>

#include <algorithm>
#include <cmath>

namespace hsm::toolpath {

using Vector2 = Eigen::Vector2d;
using Vector3 = Eigen::Vector3d;

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kFineStep = 0.1;   // mm between the next pass's balls sampled around the ridge
constexpr int kFineHalfCount = 10;  // ±1 mm of them: farther balls no longer reach a ridge below their centre

// The unit direction of a pass's plan at station k.
Vector2 planDirection(const std::vector<Vector2>& plan, size_t k) {
  const size_t before = k > 0 ? k - 1 : k, after = k + 1 < plan.size() ? k + 1 : k;
  const Vector2 chord = plan[after] - plan[before];
  return chord.norm() > 1e-12 ? Vector2(chord.normalized()) : Vector2(1.0, 0.0);
}
}  // namespace

CuspGauge::CuspGauge(const SurfaceBallDrop& ball, double toolRadius) : ball_(ball), radius_(toolRadius) {
  ball_.surface()->Bounds(u0_, u1_, v0_, v1_);
}

std::vector<BallContact> CuspGauge::contacts(const std::vector<Vector2>& plan) const {
  std::vector<BallContact> result(plan.size());
  SurfaceBallDrop::Result state;
  bool haveGuess = false;
  for (size_t i = 0; i < plan.size(); ++i) {
    haveGuess = ball_.drop(plan[i].x(), plan[i].y(), state, haveGuess);
    if (!haveGuess) continue;
    const gp_Pnt p = ball_.surface()->Value(state.u, state.v);
    result[i] = {Vector3(p.X(), p.Y(), p.Z()), state.u, state.v, state.onFace,
                 Vector3(plan[i].x(), plan[i].y(), state.tipZ + radius_)};
  }
  return result;
}

std::optional<Vector3> CuspGauge::centreAt(const Vector2& plan, SurfaceBallDrop::Result& state) const {
  if (!ball_.drop(plan.x(), plan.y(), state, true)) return std::nullopt;
  return Vector3(plan.x(), plan.y(), state.tipZ + radius_);
}

// Newton on the closest point of the surface from (u, v).
std::optional<double> CuspGauge::heightAboveFace(const Vector3& q, double u, double v, const Vector3& up) const {
  const Handle(Geom_Surface)& surface = ball_.surface();
  for (int iteration = 0; iteration < 20; ++iteration) {
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    surface->D2(u, v, p, su, sv, suu, svv, suv);
    const gp_Vec d(gp_Pnt(q.x(), q.y(), q.z()), p);
    const double f1 = d.Dot(su), f2 = d.Dot(sv);
    const double a = su.Dot(su) + d.Dot(suu), b = su.Dot(sv) + d.Dot(suv), c = sv.Dot(sv) + d.Dot(svv);
    const double det = a * c - b * b;
    if (std::abs(det) < 1e-18) return std::nullopt;
    const double du = (c * f1 - b * f2) / det, dv = (a * f2 - b * f1) / det;
    u = std::clamp(u - du, u0_, u1_);
    v = std::clamp(v - dv, v0_, v1_);
    if (std::abs(du) + std::abs(dv) < 1e-12 * (1.0 + std::abs(u) + std::abs(v))) {
      if (!ball_.inside(u, v)) return std::nullopt;
      const gp_Pnt foot = surface->Value(u, v);
      const Vector3 offset = q - Vector3(foot.X(), foot.Y(), foot.Z());
      return offset.dot(up) >= 0.0 ? offset.norm() : -offset.norm();
    }
  }
  return std::nullopt;
}

std::optional<double> CuspGauge::cusp(const std::vector<BallContact>& here, size_t k, const std::vector<Vector2>& nextPlan,
                                      const std::vector<BallContact>& next, double cuspHeight) const {
  const BallContact& m = here[k];
  const size_t before = k > 0 && here[k - 1].dropped() ? k - 1 : k;
  const size_t after = k + 1 < here.size() && here[k + 1].dropped() ? k + 1 : k;
  if (!m.inside || before == after || !next[k].dropped()) return std::nullopt;
  // The centre moves on the offset surface, square to the face normal at the contact: a chord of the
  // centre path tilts by degrees where the path bends, and the ridge is that sensitive.
  const Vector3 normal = (m.centre - m.p).normalized();  // from the face to the tool
  Vector3 tangent = here[after].centre - here[before].centre;
  tangent = (tangent - tangent.dot(normal) * normal).normalized();

  // The next pass's ball nearest the normal plane: slide along its plan (secant steps) from station k.
  const Vector2 along = planDirection(nextPlan, k);
  const double slope = tangent.head<2>().dot(along);
  SurfaceBallDrop::Result state;
  state.u = next[k].u;
  state.v = next[k].v;
  double s = 0.0;
  Vector3 centre2 = next[k].centre;
  for (int iteration = 0; iteration < 3 && std::abs(slope) > 0.2; ++iteration) {
    const double offPlane = (centre2 - m.centre).dot(tangent);
    if (std::abs(offPlane) < 1e-4) break;
    s -= offPlane / slope;
    const std::optional<Vector3> moved = centreAt(nextPlan[k] + s * along, state);
    if (!moved) return std::nullopt;
    centre2 = *moved;
  }
  const double r = radius_, offPlane = (centre2 - m.centre).dot(tangent);
  if (std::abs(offPlane) > 0.5 * r) return std::nullopt;
  const double r2 = std::sqrt(r * r - offPlane * offPlane);

  // Upper bound: the ridge between the circle and that one ball's disc.
  const Vector3 gap = centre2 - offPlane * tangent - m.centre;
  const double d = gap.norm();
  if (d >= r + r2) return kInfinity;
  if (d < 1e-12) return 0.0;
  const Vector3 toward = gap / d;
  const double a = (d * d + r * r - r2 * r2) / (2.0 * d);
  if (r * r - a * a <= 0.0) return 0.0;  // one disc within the other: no ridge
  Vector3 down = tangent.cross(toward);
  if (down.dot(normal) > 0.0) down = -down;
  const std::optional<double> bound =
      heightAboveFace(m.centre + a * toward + std::sqrt(r * r - a * a) * down, m.u, m.v, normal);
  if (!bound || *bound <= cuspHeight) return bound;

  // Exact enough: the next pass's balls every 0.1 mm around, and where the circle enters their union.
  std::vector<Vector3> balls;
  for (int i = -kFineHalfCount; i <= kFineHalfCount; ++i)
    if (const std::optional<Vector3> c = centreAt(nextPlan[k] + (s + i * kFineStep) * along, state)) balls.push_back(*c);
  auto covered = [&](const Vector3& q) {
    return std::any_of(balls.begin(), balls.end(), [&](const Vector3& c) { return (q - c).squaredNorm() < r * r; });
  };
  Vector3 side = gap - gap.dot(normal) * normal;  // in the plane, square to the normal, towards the next pass
  if (side.norm() < 1e-12) return bound;
  side.normalize();
  auto onCircle = [&](double phi) { return Vector3(m.centre + r * (-std::cos(phi) * normal + std::sin(phi) * side)); };
  if (covered(onCircle(0.0))) return 0.0;
  if (!covered(onCircle(0.5 * M_PI))) return bound;
  double outside = 0.0, inside = 0.5 * M_PI;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double mid = 0.5 * (outside + inside);
    (covered(onCircle(mid)) ? inside : outside) = mid;
  }
  const std::optional<double> exact = heightAboveFace(onCircle(outside), m.u, m.v, normal);
  return exact ? std::optional<double>(std::min(*exact, *bound)) : bound;
}

}  // namespace hsm::toolpath
