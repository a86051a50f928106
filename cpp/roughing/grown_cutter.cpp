// The cutter grown by the allowance, against part points on a curved slicing surface (grown_cutter.hpp).
#include "roughing/grown_cutter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {
constexpr double kRhoStep = 0.002;  // mm: the scan of distances from the axis
constexpr double kAcrossStep = 0.01;  // mm: the samples across x of a keep-out's ellipse
constexpr double kAlongStep = 0.01;   // the lengths tried for a keep-out's ellipse, as shares of its disk
constexpr double kLongest = 3.0;      // the longest tried, as a multiple of its disk
constexpr double kAcrossSlack = 0.02;  // mm: how much wider across than the narrowest tried it may be
constexpr double kThickestBand = 0.25;  // mm: a band below the corner where the level falls away across x
constexpr double kMostThinBands = 32.0;
}

GrownCutter::GrownCutter(const Cutter& cutter, double allowance, double concavity)
    : GrownCutter(cutter, allowance, concavity, concavity) {}

GrownCutter::GrownCutter(const Cutter& cutter, double allowance, double concavity, double concavityAcross)
    : cutter_(cutter), allowance_(allowance), concavity_(std::max(0.0, concavity)),
      across_(std::clamp(concavityAcross, 0.0, concavity_)) {}

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

std::vector<double> GrownCutter::reachAlong(double z, double convexity) const {
  const auto meets = [&](double x, double y) {
    const double rho2 = x * x + y * y;
    return std::sqrt(rho2) < width(z + 0.5 * (y * y * concavity_ + x * x * (across_ - convexity)));
  };
  std::vector<double> reach;
  double y = cutter_.radius() + allowance_;
  for (int i = 0;; ++i) {  // each x's reach is at most the last one's: scanned down from it
    while (y > 0.0 && !meets(i * kAcrossStep, y)) y -= kRhoStep;
    if (!(y > 0.0)) return reach;
    reach.push_back(y + kRhoStep);
  }
}

namespace {

// The least semi-axis across x of an ellipse `along` y that holds each sample's reach at the next sample
// across (the reach falls between): +∞ where some reach is not below `along`.
double acrossFor(const std::vector<double>& reach, double along) {
  double across = 0.0;
  for (size_t i = 0; i < reach.size(); ++i) {
    const double y = reach[i] / along;
    if (!(y < 1.0)) return std::numeric_limits<double>::infinity();
    across = std::max(across, (i + 1) * kAcrossStep / std::sqrt(1.0 - y * y));
  }
  return across;
}

// The area of a quarter of what the ellipse `e` and the disk of radius `disk` have in common.
double quarterOfBoth(const Ellipse& e, double disk) {
  constexpr int kSteps = 200;
  const double end = std::min(e.across, disk), dx = end / kSteps;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double x = (i + 0.5) * dx, u = x / e.across;
    sum += std::min(std::sqrt(std::max(0.0, disk * disk - x * x)), e.along * std::sqrt(std::max(0.0, 1.0 - u * u)));
  }
  return sum * dx;
}

}  // namespace

Ellipse GrownCutter::keepOut(double z, double convexity) const {
  const double disk = keepOut(z);
  if (!(convexity > across_) || !std::isfinite(z)) return {disk, disk};
  const std::vector<double> reach = reachAlong(z, convexity);
  // Longer ellipses reach less far across but more along the diagonals: among lengths up to three times the
  // disk's, those within kAcrossSlack of the narrowest across (a wall along y is kept nearly exactly as far as
  // the cutter reaches), the one whose common part with the disk is least.
  const double narrowest = acrossFor(reach, kLongest * disk);
  Ellipse best{disk, disk};
  double least = quarterOfBoth(best, disk);
  for (double along = disk * (1.0 + kAlongStep); along <= kLongest * disk; along += disk * kAlongStep) {
    const Ellipse e{acrossFor(reach, along), along};
    if (!(e.across < disk) || e.across > narrowest + kAcrossSlack) continue;
    const double both = quarterOfBoth(e, disk);
    if (both < least) best = e, least = both;
  }
  return best;
}

double GrownCutter::floorLift() const {
  // The floor at −(a + δ) along its normals; under the tool it stands ρ²κ/2 higher: δ is the least for which
  // no ρ meets the grown cutter.
  double lift = 0.0;
  for (double rho = 0.0; rho <= cutter_.radius() + allowance_; rho += kRhoStep)
    lift = std::max(lift, 0.5 * rho * rho * concavity_ - (lowestAt(cutter_, allowance_, rho) + allowance_));
  return lift;
}

namespace {

// The ellipse scaled about its centre to hold itself grown by `extra` every way (adding `extra` to both
// semi-axes would not, along the diagonals): stretched along its longer axis into a disk, the grown ellipse
// lies in the disk widened by `extra` times the stretch.
Ellipse widened(const Ellipse& e, double extra) {
  const double shorter = std::min(e.across, e.along);
  if (!(shorter > 0.0)) return {e.across + extra, e.along + extra};
  const double factor = (shorter + extra) / shorter;
  return {e.across * factor, e.along * factor};
}

}  // namespace

std::vector<Band> GrownCutter::bands(int count, double slack, double extra, double convexity) const {
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
  // Where the level falls away across x, a band's keep-out (its top's) is asked of points up to its
  // thickness lower, which stand lower still along the tool's line: there the bands below the corner are
  // kept thin, in at most kMostThinBands pieces whatever the concavity.
  const double thickest = convexity > across_ ? std::max(kThickestBand, (high - low) / kMostThinBands)
                                              : std::numeric_limits<double>::infinity();
  for (int k = 1; k <= count; ++k) {
    const double z1 = k == count ? high : heightFor(least + (full - least) * k / count);
    const int pieces = z1 > z0 ? std::max(1, static_cast<int>(std::ceil((z1 - z0) / thickest))) : 0;
    const double start = z0;
    for (int i = 1; i <= pieces; ++i) {
      const double to = i == pieces ? z1 : start + (z1 - start) * i / pieces;
      out.push_back({z0, to, keepOut(to) + extra});
      z0 = to;
    }
    z0 = std::max(z0, z1);
  }
  // Above the corner a point beside the tool falls back into it too, but by less than 0.1 mm across: not worth
  // the bands (each one more outline of every blade to grow).
  out.push_back({z0, std::numeric_limits<double>::infinity(), full + extra});
  const int steps = static_cast<int>(std::min<double>(kMostConvexitySteps, std::floor(convexity / kConvexityStep)));
  for (Band& band : out)
    for (int k = 1; k <= steps && std::isfinite(band.to); ++k) {
      band.convex.push_back(widened(keepOut(band.to, k * kConvexityStep), extra));
    }
  return out;
}

}  // namespace hsm::roughing
