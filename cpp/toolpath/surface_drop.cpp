#include "toolpath/surface_drop.hpp"

#include <BRep_Tool.hxx>

#include <algorithm>
#include <cmath>

namespace hsm::toolpath {

namespace {
Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Eigen::Vector3d toEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }
}  // namespace

SurfaceBallDrop::SurfaceBallDrop(const TopoDS_Face& face, double radius, double toolSide)
    : surface_(BRep_Tool::Surface(face)), dropper_(face, Eigen::Vector3d::UnitZ()), radius_(radius),
      sign_(toolSide >= 0.0 ? 1.0 : -1.0) {
  surface_->Bounds(u0_, u1_, v0_, v1_);
}

// Newton on the plan position of the ball centre C(u, v) = S + r·n, with n's derivatives from the
// Weingarten equations (second fundamental form).
bool SurfaceBallDrop::newton(double x, double y, double& u, double& v, Eigen::Vector3d& centre) const {
  for (int iteration = 0; iteration < 25; ++iteration) {
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    surface_->D2(u, v, p, su, sv, suu, svv, suv);
    const Eigen::Vector3d Su = toEigen(su), Sv = toEigen(sv);
    Eigen::Vector3d n = sign_ * Su.cross(Sv);
    const double length = n.norm();
    if (length < 1e-14) return false;
    n /= length;
    centre = toEigen(p) + radius_ * n;
    const double rx = centre.x() - x, ry = centre.y() - y;
    if (std::hypot(rx, ry) < 1e-10) return true;
    const double E = Su.dot(Su), F = Su.dot(Sv), G = Sv.dot(Sv);
    const double L = n.dot(toEigen(suu)), M = n.dot(toEigen(suv)), N = n.dot(toEigen(svv));
    const double det = E * G - F * F;
    const Eigen::Vector3d nu = ((F * M - G * L) * Su + (F * L - E * M) * Sv) / det;
    const Eigen::Vector3d nv = ((F * N - G * M) * Su + (F * M - E * N) * Sv) / det;
    const Eigen::Vector3d Cu = Su + radius_ * nu, Cv = Sv + radius_ * nv;
    const double a = Cu.x(), b = Cv.x(), c = Cu.y(), d = Cv.y();
    const double j = a * d - b * c;
    if (std::abs(j) < 1e-14) return false;
    u = std::clamp(u - (d * rx - b * ry) / j, u0_, u1_);
    v = std::clamp(v - (a * ry - c * rx) / j, v0_, v1_);
  }
  return false;
}

bool SurfaceBallDrop::drop(double x, double y, Result& result, bool haveGuess) const {
  double u = result.u, v = result.v;
  Eigen::Vector3d centre;
  bool found = haveGuess && newton(x, y, u, v, centre);
  if (!found) {
    Eigen::RowVector3d start(x, y, 0.0);
    double gu = result.u, gv = result.v;
    if (!dropper_.dropOne(start, gu, gv, haveGuess)) return false;
    u = gu;
    v = gv;
    found = newton(x, y, u, v, centre);
  }
  if (!found) return false;
  result.tipZ = centre.z() - radius_;
  result.u = u;
  result.v = v;
  // The ball rests on the contact from above only where the tool side's normal points up: the centre is
  // above the contact point.
  gp_Pnt contact;
  gp_Vec su, sv;
  surface_->D1(u, v, contact, su, sv);
  const bool fromAbove = centre.z() > contact.Z() + 1e-9 * radius_;
  result.onFace = fromAbove && dropper_.inside(u, v);
  return true;
}

}  // namespace hsm::toolpath
