#include "geometry/face_drop.hpp"

#include "common/error.hpp"

#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hsm::geometry {

namespace {
Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Eigen::Vector3d toEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }
}  // namespace

FaceDropper::FaceDropper(const TopoDS_Face& face, const Eigen::Vector3d& axis)
    : face_(face), surface_(BRep_Tool::Surface(face)), axis_(axis.normalized()) {
  if (surface_.IsNull()) throw InputError("the face has no surface: pass a face of the model");
  analysis_ = new ShapeAnalysis_Surface(surface_);
  surface_->Bounds(u0_, u1_, v0_, v1_);
  e1_ = axis_.unitOrthogonal();
  e2_ = axis_.cross(e1_);
}

FaceDropper::~FaceDropper() = default;

bool FaceDropper::dropOne(Eigen::Ref<Eigen::RowVector3d> point, double& u, double& v, bool haveGuess) const {
  const Eigen::Vector3d target = point.transpose();
  if (!haveGuess) {
    const gp_Pnt2d uv = analysis_->ValueOfUV(gp_Pnt(target.x(), target.y(), target.z()), 1e-6);
    u = uv.X();
    v = uv.Y();
  }
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
    haveGuess = dropOne(points.row(i), u, v, haveGuess);
    if (!haveGuess) ++failures;
  }
  return failures;
}

std::vector<char> FaceDropper::dropAndClassify(PointArray& points) const {
  std::vector<char> inside(static_cast<size_t>(points.rows()), 0);
  bool haveGuess = false;
  double u = 0.0, v = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    haveGuess = dropOne(points.row(i), u, v, haveGuess);
    if (!haveGuess) continue;
    if (!classifier_) classifier_ = std::make_unique<BRepTopAdaptor_FClass2d>(face_, 1e-7);
    inside[static_cast<size_t>(i)] = classifier_->Perform(gp_Pnt2d(u, v)) != TopAbs_OUT;
  }
  return inside;
}

}  // namespace hsm::geometry
