#include "roughing/meridian.hpp"

#include "roughing/slicing.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

Meridian::Meridian(const TopoDS_Face& face, const Eigen::Vector3d& axisPoint, const Eigen::Vector3d& axis, int samples,
                   double extension)
    : axisPoint_(axisPoint), axis_(axis.normalized()) {
  // Over the surface's v range where it is a bounded curve (a B-spline's, beyond the face), else over the
  // face's (a periodic meridian, an ellipse's whole turn, would loop).
  BRepAdaptor_Surface surface(face, Standard_False);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const bool whole = !surface.IsVPeriodic() && std::isfinite(surface.FirstVParameter()) &&
                     std::isfinite(surface.LastVParameter()) && !surface.IsVClosed();
  const double vFirst = whole ? surface.FirstVParameter() : v0, vLast = whole ? surface.LastVParameter() : v1;
  for (int i = 0; i < samples; ++i) {
    const gp_Pnt p = surface.Value(0.5 * (u0 + u1), vFirst + (vLast - vFirst) * i / (samples - 1));
    samples_.push_back(plane({p.X(), p.Y(), p.Z()}));
  }
  // The side of the volume: the face's inward normal at its centre, in the meridian plane.
  Eigen::Vector3d centre;
  const Eigen::Vector3d inward = inwardNormalAtCentre(face, centre);
  const Eigen::Vector2d c = plane(centre), towards = plane(centre + 1e-3 * std::max(1.0, extension) * inward) - c;
  size_t nearest = 0;
  for (size_t i = 1; i < samples_.size(); ++i)
    if ((samples_[i] - c).squaredNorm() < (samples_[nearest] - c).squaredNorm()) nearest = i;
  sign_ = 1.0;
  sign_ = sampleNormal(nearest).dot(towards) >= 0.0 ? 1.0 : -1.0;

  // The extended polyline: the ends along their tangents, stopping short of the axis (ρ > 0).
  auto extended = [&](const Eigen::Vector2d& end, const Eigen::Vector2d& along) {
    const double length = along.x() < -1e-9 ? std::min(extension, (end.x() - 1e-3) / -along.x()) : extension;
    return Eigen::Vector2d(end + std::max(0.0, length) * along);
  };
  const size_t n = samples_.size();
  const Eigen::Vector2d before = extended(samples_[0], (samples_[0] - samples_[1]).normalized());
  const Eigen::Vector2d after = extended(samples_[n - 1], (samples_[n - 1] - samples_[n - 2]).normalized());
  vertices_.push_back(before);
  normals_.push_back(sampleNormal(0));
  for (size_t i = 0; i < n; ++i) vertices_.push_back(samples_[i]), normals_.push_back(sampleNormal(i));
  vertices_.push_back(after);
  normals_.push_back(sampleNormal(n - 1));
  arc_.push_back(0.0);
  for (size_t i = 1; i < vertices_.size(); ++i) arc_.push_back(arc_.back() + (vertices_[i] - vertices_[i - 1]).norm());
}

Eigen::Vector2d Meridian::plane(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d w = p - axisPoint_;
  const double z = axis_.dot(w);
  return {(w - z * axis_).norm(), z};
}

Eigen::Vector2d Meridian::sampleNormal(size_t i) const {
  const Eigen::Vector2d t = samples_[std::min(i + 1, samples_.size() - 1)] - samples_[i > 0 ? i - 1 : 0];
  return sign_ * Eigen::Vector2d(-t.y(), t.x()).normalized();
}

double Meridian::distance(const Eigen::Vector2d& q) const {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < samples_.size(); ++i) {
    const Eigen::Vector2d a = samples_[i], m = samples_[i + 1] - a;
    const double t = std::clamp(m.dot(q - a) / std::max(m.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (q - (a + t * m)).squaredNorm());
  }
  return std::sqrt(best);
}

std::optional<Meridian::Place> Meridian::locate(const Eigen::Vector2d& q) const {
  std::optional<Place> best;
  // A normal line of the segment passes through q where the side q is on changes between its ends' normals
  // (a second crossing inside a segment, beyond the centres of curvature, is not looked for).
  double sideBefore = cross(q - vertices_[0], normals_[0]);
  for (size_t i = 0; i + 1 < vertices_.size(); ++i) {
    const double sideAfter = cross(q - vertices_[i + 1], normals_[i + 1]);
    const bool crosses = (sideBefore <= 0.0) != (sideAfter <= 0.0) || sideBefore == 0.0 || sideAfter == 0.0;
    sideBefore = sideAfter;
    if (!crosses) continue;
    // (A − tB) × (C + tD) = 0: A = q − M_i, B = ΔM, C = N_i, D = ΔN.
    const Eigen::Vector2d A = q - vertices_[i], B = vertices_[i + 1] - vertices_[i];
    const Eigen::Vector2d C = normals_[i], D = normals_[i + 1] - normals_[i];
    const double c0 = cross(A, C), c1 = cross(A, D) - cross(B, C), c2 = -cross(B, D);
    double roots[2];
    int count = 0;
    if (std::abs(c2) < 1e-12 * (std::abs(c1) + std::abs(c0) + 1e-300)) {
      if (std::abs(c1) > 0.0) roots[count++] = -c0 / c1;
    } else {
      const double disc = c1 * c1 - 4.0 * c2 * c0;
      if (disc >= 0.0) {
        // The stable pair of roots.
        const double k = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        roots[count++] = k / c2;
        if (k != 0.0) roots[count++] = c0 / k;
      }
    }
    for (int r = 0; r < count; ++r) {
      const double t = roots[r];
      if (!(t >= -1e-9 && t <= 1.0 + 1e-9)) continue;
      const double tc = std::clamp(t, 0.0, 1.0);
      const Eigen::Vector2d n = C + tc * D;
      const double d = (A - tc * B).dot(n) / n.norm();
      if (!best || std::abs(d) < std::abs(best->d)) best = Place{arc_[i] + tc * B.norm(), d};
    }
  }
  return best;
}

size_t Meridian::segmentOf(double s) const {
  const auto it = std::upper_bound(arc_.begin(), arc_.end(), s);
  const size_t i = it == arc_.begin() ? 0 : static_cast<size_t>(it - arc_.begin()) - 1;
  return std::min(i, vertices_.size() - 2);
}

Eigen::Vector2d Meridian::normal(double s) const {
  const size_t i = segmentOf(s);
  const double t = (s - arc_[i]) / std::max(arc_[i + 1] - arc_[i], 1e-300);
  return ((1.0 - t) * normals_[i] + t * normals_[i + 1]).normalized();
}

Eigen::Vector2d Meridian::at(double s, double d) const {
  const size_t i = segmentOf(s);
  const double t = (s - arc_[i]) / std::max(arc_[i + 1] - arc_[i], 1e-300);
  return (1.0 - t) * vertices_[i] + t * vertices_[i + 1] + d * normal(s);
}

double Meridian::stretch(double s, double d) const {
  const double h = 1e-3;
  return (at(s + h, d) - at(s - h, d)).norm() / (2.0 * h);
}

}  // namespace hsm::roughing
