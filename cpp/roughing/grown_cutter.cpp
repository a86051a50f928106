// The cutter grown by the allowance, against part points on a curved slicing surface (grown_cutter.hpp).
#include "roughing/grown_cutter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {
constexpr double kRhoStep = 0.002;  // mm: the scan of distances from the axis
}

GrownCutter::GrownCutter(const Cutter& cutter, double allowance, double concavity)
    : cutter_(cutter), allowance_(allowance), concavity_(std::max(0.0, concavity)) {}

double GrownCutter::width(double z) const {
  const double r = cutter_.corner(), a = allowance_;
  if (z < -a) return 0.0;
  if (z >= r) return cutter_.radius() + a;
  const double d = r - z;
  return cutter_.radius() - r + std::sqrt(std::max(0.0, (r + a) * (r + a) - d * d));
}

double GrownCutter::lowestAt(const Cutter& cutter, double grow, double rho) {
  const double flat = cutter.radius() - cutter.corner();
  if (rho <= flat) return -grow;
  const double d = rho - flat, g = cutter.corner() + grow;
  if (d > g) return std::numeric_limits<double>::infinity();
  return cutter.corner() - std::sqrt(std::max(0.0, g * g - d * d));
}

double GrownCutter::keepOut(double z) const {
  // The largest ρ with ρ < width(z + ρ²κ/2): scanned down from the widest the grown cutter is.
  for (double rho = cutter_.radius() + allowance_; rho > 0.0; rho -= kRhoStep)
    if (rho < width(z + 0.5 * rho * rho * concavity_)) return rho + kRhoStep;
  return width(z) > 0.0 ? kRhoStep : 0.0;
}

double GrownCutter::floorLift() const {
  // The floor at −(a + δ) along its normals; under the tool it stands ρ²κ/2 higher: δ is the least for which
  // no ρ meets the grown cutter.
  double lift = 0.0;
  for (double rho = 0.0; rho <= cutter_.radius() + allowance_; rho += kRhoStep)
    lift = std::max(lift, 0.5 * rho * rho * concavity_ - (lowestAt(cutter_, allowance_, rho) + allowance_));
  return lift;
}

std::vector<Band> GrownCutter::bands(int count, double slack, double extra) const {
  const double full = cutter_.radius() + allowance_;
  // Below `low` no point meets the cutter, from `high` up every point asks for the full keep-out.
  const double low = -allowance_ - 0.5 * full * full * concavity_, high = cutter_.corner();
  auto heightFor = [&](double target) {  // the least height whose keep-out reaches `target` (it grows with z)
    double lo = low, hi = high;
    for (int k = 0; k < 50; ++k) {
      const double mid = 0.5 * (lo + hi);
      (keepOut(mid) >= target ? hi : lo) = mid;
    }
    return hi;
  };
  std::vector<Band> out;
  double z0 = heightFor(kRhoStep) + slack;
  const double least = keepOut(z0);  // the flat bottom's R − r where the surface is flat
  for (int k = 1; k <= count; ++k) {
    const double z1 = k == count ? high : heightFor(least + (full - least) * k / count);
    if (z1 > z0) out.push_back({z0, z1, keepOut(z1) + extra});
    z0 = std::max(z0, z1);
  }
  out.push_back({z0, std::numeric_limits<double>::infinity(), full + extra});
  return out;
}

}  // namespace hsm::roughing
