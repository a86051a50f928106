#include "geometry/face_drop.hpp"

#include "common/error.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace hsm::geometry {

namespace {
Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Eigen::Vector3d toEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }
}  // namespace

UVClassifier::UVClassifier(const TopoDS_Face& face) {
  constexpr int kSamplesPerEdge = 400;
  double vMax = -1e300;
  vMin_ = 1e300;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    double first = 0.0, last = 0.0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(it.Current()), face, first, last);
    if (pcurve.IsNull()) continue;
    gp_Pnt2d previous = pcurve->Value(first);
    for (int k = 1; k <= kSamplesPerEdge; ++k) {
      const gp_Pnt2d p = pcurve->Value(first + (last - first) * k / kSamplesPerEdge);
      segments_.push_back({previous.X(), previous.Y(), p.X(), p.Y()});
      vMin_ = std::min({vMin_, previous.Y(), p.Y()});
      vMax = std::max({vMax, previous.Y(), p.Y()});
      previous = p;
    }
  }
  if (segments_.empty()) throw InputError("the face has no boundary in its parameters: pass a trimmed face");
  const int bands = 512;
  bandHeight_ = std::max((vMax - vMin_) / bands, 1e-12);
  bands_.resize(bands);
  for (size_t i = 0; i < segments_.size(); ++i) {
    const Segment& s = segments_[i];
    const int b0 = std::clamp(int((std::min(s.v0, s.v1) - vMin_) / bandHeight_), 0, bands - 1);
    const int b1 = std::clamp(int((std::max(s.v0, s.v1) - vMin_) / bandHeight_), 0, bands - 1);
    for (int b = b0; b <= b1; ++b) bands_[b].push_back(static_cast<int>(i));
  }
}

bool UVClassifier::inside(double u, double v) const {
  const int band = int((v - vMin_) / bandHeight_);
  if (band < 0 || band >= static_cast<int>(bands_.size())) return false;
  bool in = false;
  for (int i : bands_[band]) {
    const Segment& s = segments_[i];
    if ((s.v0 > v) != (s.v1 > v) && u < s.u0 + (v - s.v0) * (s.u1 - s.u0) / (s.v1 - s.v0)) in = !in;
  }
  return in;
}

UVLocator::UVLocator(const Handle(Geom_Surface)& surface, double u0, double u1, double v0, double v1) {
  constexpr int kSamples = 128;
  std::vector<std::array<double, 4>> samples;  // x, y, u, v
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  for (int i = 0; i <= kSamples; ++i)
    for (int j = 0; j <= kSamples; ++j) {
      const double u = u0 + (u1 - u0) * i / kSamples, v = v0 + (v1 - v0) * j / kSamples;
      const gp_Pnt p = surface->Value(u, v);
      samples.push_back({p.X(), p.Y(), u, v});
      xmin = std::min(xmin, p.X());
      xmax = std::max(xmax, p.X());
      ymin = std::min(ymin, p.Y());
      ymax = std::max(ymax, p.Y());
    }
  cell_ = std::max({(xmax - xmin) / kSamples, (ymax - ymin) / kSamples, 1e-6});
  x0_ = xmin - cell_;
  y0_ = ymin - cell_;
  nx_ = int((xmax - x0_) / cell_) + 3;
  ny_ = int((ymax - y0_) / cell_) + 3;
  u_.assign(static_cast<size_t>(nx_) * ny_, std::nanf(""));
  v_ = u_;
  std::vector<float> best(u_.size(), 1e30f);
  // Each sample claims the cells around it it is nearest to (a 5 × 5 neighbourhood covers the gaps
  // where the surface is steep in plan).
  for (const auto& s : samples) {
    const int ci = int((s[0] - x0_) / cell_), cj = int((s[1] - y0_) / cell_);
    for (int dj = -2; dj <= 2; ++dj)
      for (int di = -2; di <= 2; ++di) {
        const int i = ci + di, j = cj + dj;
        if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
        const double cx = x0_ + (i + 0.5) * cell_, cy = y0_ + (j + 0.5) * cell_;
        const float d = float(std::hypot(cx - s[0], cy - s[1]));
        const size_t k = static_cast<size_t>(j) * nx_ + i;
        if (d < best[k]) {
          best[k] = d;
          u_[k] = float(s[2]);
          v_[k] = float(s[3]);
        }
      }
  }
}

bool UVLocator::guess(double x, double y, double& u, double& v) const {
  const int i = int((x - x0_) / cell_), j = int((y - y0_) / cell_);
  if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return false;
  const size_t k = static_cast<size_t>(j) * nx_ + i;
  if (std::isnan(u_[k])) return false;
  u = u_[k];
  v = v_[k];
  return true;
}

FaceDropper::FaceDropper(const TopoDS_Face& face, const Eigen::Vector3d& axis)
    : face_(face), surface_(face.IsNull() ? Handle(Geom_Surface)() : BRep_Tool::Surface(face)), axis_(axis.normalized()) {
  if (surface_.IsNull()) throw InputError("the face has no surface: pass a face of the model");
  if (!axis.allFinite() || axis.norm() < 1e-12)
    throw InputError("the axis to drop points along is zero or not finite: pass a unit vector, e.g. (0, 0, 1)");
  analysis_ = new ShapeAnalysis_Surface(surface_);
  surface_->Bounds(u0_, u1_, v0_, v1_);
  if (std::abs(axis_.z()) > 0.999) {
    // Over the face's own parameters (a surface may be infinite), widened a little, within the surface.
    double fu0, fu1, fv0, fv1;
    BRepTools::UVBounds(face, fu0, fu1, fv0, fv1);
    const double du = 0.1 * (fu1 - fu0), dv = 0.1 * (fv1 - fv0);
    locator_ = std::make_unique<UVLocator>(surface_, std::max(u0_, fu0 - du), std::min(u1_, fu1 + du),
                                           std::max(v0_, fv0 - dv), std::min(v1_, fv1 + dv));
  }
  e1_ = axis_.unitOrthogonal();
  e2_ = axis_.cross(e1_);
}

FaceDropper::~FaceDropper() = default;

bool FaceDropper::dropOne(Eigen::Ref<Eigen::RowVector3d> point, double& u, double& v, bool haveGuess) const {
  // Newton from the previous point's parameters (the usual case: points follow each other); if that
  // fails, once more from the point's projection on the surface (slower, but from anywhere).
  if (haveGuess && newton(point, u, v)) return true;
  const Eigen::Vector3d target = point.transpose();
  double u1 = 0.0, v1 = 0.0;
  if (locator_) {
    if (!locator_->guess(target.x(), target.y(), u1, v1)) return false;  // not above the surface at all
  } else {
    const gp_Pnt2d uv = analysis_->ValueOfUV(gp_Pnt(target.x(), target.y(), target.z()), 1e-6);
    u1 = uv.X();
    v1 = uv.Y();
  }
  if (!newton(point, u1, v1)) return false;
  u = u1;
  v = v1;
  return true;
}

bool FaceDropper::newton(Eigen::Ref<Eigen::RowVector3d> point, double& u, double& v) const {
  const Eigen::Vector3d target = point.transpose();
  // Newton on the two plan components of S(u,v) - target (the component along the axis is free).
  for (int iteration = 0; iteration < 30; ++iteration) {
    gp_Pnt p;
    gp_Vec su, sv;
    surface_->D1(u, v, p, su, sv);
    const Eigen::Vector3d r = toEigen(p) - target;
    const double r1 = e1_.dot(r), r2 = e2_.dot(r);
    if (std::hypot(r1, r2) < 1e-9) {
      point = toEigen(p).transpose();
      return true;
    }
    const double a = e1_.dot(toEigen(su)), b = e1_.dot(toEigen(sv));
    const double c = e2_.dot(toEigen(su)), d = e2_.dot(toEigen(sv));
    const double det = a * d - b * c;
    if (std::abs(det) < 1e-14) return false;  // the surface is vertical here: no drop along the axis
    u = std::clamp(u - (d * r1 - b * r2) / det, u0_, u1_);
    v = std::clamp(v - (a * r2 - c * r1) / det, v0_, v1_);
  }
  return false;
}

int FaceDropper::drop(PointArray& points) const {
  int failures = 0;
  bool haveGuess = false;
  double u = 0.0, v = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const bool dropped = dropOne(points.row(i), u, v, haveGuess);
    haveGuess = haveGuess || dropped;
    if (!dropped) ++failures;
  }
  return failures;
}

std::vector<char> FaceDropper::dropAndClassify(PointArray& points) const {
  std::vector<char> inside(static_cast<size_t>(points.rows()), 0);
  bool haveGuess = false;
  double u = 0.0, v = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const bool dropped = dropOne(points.row(i), u, v, haveGuess);
    haveGuess = haveGuess || dropped;
    if (dropped) inside[static_cast<size_t>(i)] = this->inside(u, v);
  }
  return inside;
}

bool FaceDropper::inside(double u, double v) const {
  if (!classifier_) classifier_ = std::make_unique<UVClassifier>(face_);
  return classifier_->inside(u, v);
}

}  // namespace hsm::geometry
