#include "curvenet/plane_cuts.hpp"

#include "common/error.hpp"

#include <Extrema_LocateExtPC.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include <algorithm>
#include <cmath>

namespace hsm::curvenet::detail {

namespace {
constexpr double kCutTolerance = 1e-9;  // mm along d

Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Eigen::Vector3d toEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

// Enough samples that each knot span is cut at most a few times between two samples.
int tableSize(const Handle(Geom_BSplineCurve)& curve) {
  return std::clamp(40 * curve->NbKnots(), 400, 20000);
}
}  // namespace

Handle(Geom_BSplineCurve) orientedAlong(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& direction) {
  const double s0 = direction.dot(toEigen(curve->StartPoint()));
  const double s1 = direction.dot(toEigen(curve->EndPoint()));
  Handle(Geom_BSplineCurve) copy = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  if (s1 < s0) copy->Reverse();
  return copy;
}

PlaneCutter::PlaneCutter(Handle(Geom_BSplineCurve) curve, const Eigen::Vector3d& direction)
    : curve_(orientedAlong(curve, direction)), direction_(direction) {
  const int n = tableSize(curve_);
  const double t0 = curve_->FirstParameter(), t1 = curve_->LastParameter();
  t_.resize(n);
  s_.resize(n);
  for (int i = 0; i < n; ++i) {
    t_[i] = t0 + (t1 - t0) * i / (n - 1);
    s_[i] = station(t_[i]);
  }
  const auto [lo, hi] = std::minmax_element(s_.begin(), s_.end());
  sMin_ = *lo;
  sMax_ = *hi;
}

double PlaneCutter::station(double t) const { return direction_.dot(toEigen(curve_->Value(t))); }

double PlaneCutter::refine(double ta, double tb, double s) const {
  double fa = station(ta) - s;
  if (std::abs(fa) <= kCutTolerance) return ta;
  double t = 0.5 * (ta + tb);
  for (int i = 0; i < 60; ++i) {
    gp_Pnt p;
    gp_Vec d1;
    curve_->D1(t, p, d1);
    const double f = direction_.dot(toEigen(p)) - s;
    if (std::abs(f) <= kCutTolerance) return t;
    if ((f < 0) == (fa < 0)) {
      ta = t;
      fa = f;
    } else {
      tb = t;
    }
    const double slope = direction_.dot(toEigen(d1));
    const double newton = slope != 0.0 ? t - f / slope : ta - 1.0;
    t = (newton > ta && newton < tb) ? newton : 0.5 * (ta + tb);  // bisection when Newton leaves the bracket
  }
  return t;
}

PlaneCutter::Cuts PlaneCutter::cut(const std::vector<double>& stations) const {
  Cuts cuts;
  cuts.points.resize(static_cast<Eigen::Index>(stations.size()), 3);
  double previous = curve_->FirstParameter();
  for (size_t k = 0; k < stations.size(); ++k) {
    const double s = stations[k];
    std::vector<double> found;
    for (size_t i = 0; i + 1 < s_.size(); ++i) {
      const double a = s_[i] - s, b = s_[i + 1] - s;
      if (a == 0.0) {
        if (found.empty() || found.back() != t_[i]) found.push_back(t_[i]);
      } else if (b == 0.0) {
        found.push_back(t_[i + 1]);
      } else if ((a < 0) != (b < 0)) {
        found.push_back(refine(t_[i], t_[i + 1], s));
      }
    }
    if (found.empty())
      throw ComputationError("the plane at " + std::to_string(s) + " mm along the machining direction misses a curve "
                             "it should cut (curve extent " + std::to_string(sMin_) + ".." + std::to_string(sMax_) +
                             " mm)");
    if (found.size() > 1) cuts.multiCutStations.push_back(static_cast<int>(k));
    // Continuation rule: the first cut at or after the previous one in the curve's order, else the closest.
    auto next = std::find_if(found.begin(), found.end(), [&](double t) { return t >= previous - 1e-12; });
    const double chosen = next != found.end() ? *next : found.back();
    previous = chosen;
    cuts.points.row(static_cast<Eigen::Index>(k)) = toEigen(curve_->Value(chosen)).transpose();
  }
  return cuts;
}

std::pair<Handle(Geom_BSplineCurve), double> fitCurve(const PointArray& points, double tolerance) {
  const int n = static_cast<int>(points.rows());
  if (n < 2) throw InputError("an intermediate curve needs at least 2 planes; use a smaller step P");
  if (n > kMaxPlanes + 1)  // the layout refuses such steps; a guard for OCCT's approximation, which fails past it
    throw InputError("an intermediate curve on " + std::to_string(n) + " planes exceeds the limit of " +
                     std::to_string(kMaxPlanes) + ": use a larger step P");
  TColgp_Array1OfPnt array(1, n);
  for (int i = 0; i < n; ++i) array.SetValue(i + 1, gp_Pnt(points(i, 0), points(i, 1), points(i, 2)));
  const int degree = std::min(5, n - 1);
  Handle(Geom_BSplineCurve) curve;
  try {
    GeomAPI_PointsToBSpline fit(array, Approx_ChordLength, degree, degree, degree >= 3 ? GeomAbs_C2 : GeomAbs_C1,
                                tolerance);
    if (!fit.IsDone()) throw ComputationError("OCCT could not fit a B-spline to the intermediate points");
    curve = fit.Curve();
  } catch (const Standard_Failure& failure) {
    throw ComputationError(std::string("OCCT failed to fit an intermediate curve: ") + failure.GetMessageString());
  }
  // A fit whose poles fly far from its points oscillates between them; refuse it rather than hand on a
  // curve that later operations (face split, sampling) cannot digest.
  Eigen::AlignedBox3d pointBox, poleBox;
  for (int i = 0; i < n; ++i) pointBox.extend(Eigen::Vector3d(points.row(i).transpose()));
  for (int i = 1; i <= curve->NbPoles(); ++i) {
    const gp_Pnt pole = curve->Pole(i);
    poleBox.extend(Eigen::Vector3d(pole.X(), pole.Y(), pole.Z()));
  }
  const double size = std::max(pointBox.diagonal().norm(), 1.0);
  if ((poleBox.min() - pointBox.min()).minCoeff() < -size || (poleBox.max() - pointBox.max()).maxCoeff() > size)
    throw ComputationError("the B-spline fitted to an intermediate curve oscillates between its points: use a "
                           "larger step P or fit tolerance");
  // The deviation is measured, not assumed: the approximation may stop short of the tolerance.
  GeomAdaptor_Curve adaptor(curve);
  const double t0 = curve->FirstParameter(), t1 = curve->LastParameter();
  double deviation = 0.0, guess = t0;
  double chord = 0.0, total = 0.0;
  for (int i = 1; i < n; ++i) total += array(i + 1).Distance(array(i));
  for (int i = 0; i < n; ++i) {
    if (i > 0) chord += array(i + 1).Distance(array(i));
    guess = total > 0 ? t0 + (t1 - t0) * chord / total : t0;
    Extrema_LocateExtPC locate(array(i + 1), adaptor, guess, 1e-10);
    const double distance = locate.IsDone() ? std::sqrt(locate.SquareDistance())
                                            : array(i + 1).Distance(curve->Value(guess));
    deviation = std::max(deviation, distance);
  }
  return {curve, deviation};
}

}  // namespace hsm::curvenet::detail
