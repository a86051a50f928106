#include "kinematics/profile.hpp"

#include <algorithm>
#include <cmath>

namespace hsm::kinematics {


double reachableSpeed(double v0, double distance, const Dynamics& d) {
  if (distance <= 0.0) return v0;
  const double a = d.acceleration;
  if (!d.jerkLimited) return std::sqrt(v0 * v0 + 2.0 * a * distance);
  const double j = d.jerk;
  // Jerk only: distance = (2·v0 + s²)·s/√J with s = sqrt(Δv): s³ + p·s − q = 0, one real root (Cardano).
  const double p = 2.0 * v0, q = distance * std::sqrt(j);
  const double root = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
  const double s = cubeRoot(q / 2.0 + root) + cubeRoot(q / 2.0 - root);
  const double dv = s * s;
  if (dv <= a * a / j) return v0 + dv;
  // Acceleration reached: (v1² − v0²)/(2A) + (v0 + v1)·A/(2J) = distance, a quadratic in v1.
  const double b = a * a / j;
  const double c = v0 * b - v0 * v0 - 2.0 * a * distance;
  return 0.5 * (-b + std::sqrt(b * b - 4.0 * c));
}

namespace {
// The speed at which accelerating from v0 and decelerating to v1 take `length` together, within [lo, hi]: regula
// falsi with the Illinois halving (the distance grows smoothly with the speed, so it converges in a few steps
// where bisection takes some thirty), kept to the bracket.
double jerkLimitedPeak(double length, double v0, double v1, double lo, double hi, const Dynamics& d) {
  auto excess = [&](double v) { return changeDistance(v0, v, d) + changeDistance(v, v1, d) - length; };
  double fLo = excess(lo), fHi = excess(hi);
  if (fLo >= 0.0) return lo;
  int side = 0;
  for (int i = 0; i < 100 && hi - lo > 1e-9 * (1.0 + hi); ++i) {
    double v = (lo * fHi - hi * fLo) / (fHi - fLo);
    if (!(v > lo && v < hi)) v = 0.5 * (lo + hi);
    const double f = excess(v);
    if (std::abs(f) <= 1e-12 * length) return v;
    if (f > 0.0) {
      hi = v;
      fHi = f;
      if (side == -1) fLo *= 0.5;
      side = -1;
    } else {
      lo = v;
      fLo = f;
      if (side == 1) fHi *= 0.5;
      side = 1;
    }
  }
  return lo;
}
}  // namespace

BlockProfile blockProfile(double length, double v0, double v1, double vCruise, const Dynamics& d) {
  BlockProfile profile;
  profile.v0 = v0;
  profile.v1 = v1;
  const double up = changeDistance(v0, vCruise, d), down = changeDistance(vCruise, v1, d);
  double peak = vCruise;
  if (up + down > length) {
    // No cruise: the peak where accelerating and decelerating distances add up to the length.
    double lo = std::max(v0, v1), hi = vCruise;
    if (!d.jerkLimited) {
      peak = std::sqrt(std::max(lo * lo, (2.0 * d.acceleration * length + v0 * v0 + v1 * v1) / 2.0));
    } else {
      peak = jerkLimitedPeak(length, v0, v1, lo, hi, d);
    }
    peak = std::min(peak, vCruise);
  }
  profile.peak = peak;
  profile.accelTime = changeTime(v0, peak, d);
  profile.decelTime = changeTime(peak, v1, d);
  const double rest = length - changeDistance(v0, peak, d) - changeDistance(peak, v1, d);
  profile.cruiseTime = peak > 0.0 ? std::max(0.0, rest) / peak : 0.0;
  profile.time = profile.accelTime + profile.cruiseTime + profile.decelTime;
  return profile;
}

namespace {
// State `t` into a change from v0 to v1 that lasts `duration` (t in [0, duration]).
ProfileState changeStateAt(double v0, double v1, double duration, double t, const Dynamics& d) {
  if (duration <= 0.0) return {0.0, v0};
  const double sign = v1 >= v0 ? 1.0 : -1.0, dv = std::abs(v1 - v0);
  if (!d.jerkLimited) {
    const double a = sign * dv / duration;
    return {v0 * t + 0.5 * a * t * t, v0 + a * t};
  }
  const double j = d.jerk;
  const double ramp = std::min(d.acceleration / j, 0.5 * duration);  // time to reach the top acceleration
  const double top = j * ramp;
  // Phases: jerk up for `ramp`, constant acceleration for `hold`, jerk down for `ramp`.
  const double hold = duration - 2.0 * ramp;
  double s = 0.0, v = v0;
  auto advance = [&](double dt, double a0, double jj) {
    s += v * dt + 0.5 * sign * a0 * dt * dt + sign * jj * dt * dt * dt / 6.0;
    v += sign * (a0 * dt + 0.5 * jj * dt * dt);
  };
  if (t <= ramp) {
    advance(t, 0.0, j);
    return {s, v};
  }
  advance(ramp, 0.0, j);
  if (t <= ramp + hold) {
    advance(t - ramp, top, 0.0);
    return {s, v};
  }
  advance(hold, top, 0.0);
  advance(t - ramp - hold, top, -j);
  return {s, v};
}
}  // namespace

ProfileState stateAt(const BlockProfile& p, double t, const Dynamics& d) {
  t = std::clamp(t, 0.0, p.time);
  if (t <= p.accelTime) return changeStateAt(p.v0, p.peak, p.accelTime, t, d);
  const double accelDistance = changeDistance(p.v0, p.peak, d);
  if (t <= p.accelTime + p.cruiseTime) return {accelDistance + p.peak * (t - p.accelTime), p.peak};
  const ProfileState tail = changeStateAt(p.peak, p.v1, p.decelTime, t - p.accelTime - p.cruiseTime, d);
  return {accelDistance + p.peak * p.cruiseTime + tail.distance, tail.speed};
}

}  // namespace hsm::kinematics
