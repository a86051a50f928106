#include "geometry/plane_cutter.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace hsm::geometry {

namespace {
constexpr double kCutTolerance = 1e-9;  // mm along d
// A plane this close beyond the curve's end still cuts it there: a station placed at one curve's end misses a
// curve that ends a rounding error short of it (a boundary read back from a saved document, a fitted curve).
constexpr double kEndTolerance = 1e-6;  // mm along d

std::string millimetres(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

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
    if (found.empty()) {
      const auto nearest = std::min_element(s_.begin(), s_.end(), [s](double a, double b) {
        return std::abs(a - s) < std::abs(b - s);
      });
      if (std::abs(*nearest - s) <= kEndTolerance) found.push_back(t_[nearest - s_.begin()]);
    }
    if (found.empty())
      throw ComputationError("the plane at " + millimetres(s) + " mm along the machining direction misses a curve "
                             "it should cut (curve extent " + millimetres(sMin_) + ".." + millimetres(sMax_) +
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

}  // namespace hsm::geometry
