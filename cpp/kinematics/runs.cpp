#include "kinematics/runs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::kinematics::detail {

namespace {
constexpr size_t kLongestRun = 100000;  // blocks; a longer run is cut (memory stays bounded)
constexpr double kSlack = 1e-9;         // relative: a profile this much above a limit still respects it
}  // namespace

double timeAtDistance(const BlockProfile& p, double distance, const Dynamics& d, double since, double sinceDistance,
                      double sinceSpeed) {
  const double up = changeDistance(p.v0, p.peak, d);
  if (distance <= 0.0) return 0.0;
  if (distance >= up && distance <= up + p.peak * p.cruiseTime)
    return p.accelTime + (distance - up) / p.peak;  // the cruise: linear
  const bool hinted = sinceSpeed > 1e-12 && sinceDistance <= distance;
  double lo = hinted ? since : 0.0, hi = p.time;
  double t = std::clamp(hinted ? since + (distance - sinceDistance) / sinceSpeed
                               : distance / std::max(0.5 * (p.v0 + p.peak), 1e-12), lo, hi);
  for (int i = 0; i < 60; ++i) {
    const ProfileState s = stateAt(p, t, d);
    const double error = s.distance - distance;
    if (std::abs(error) <= 1e-12 * (1.0 + distance)) return t;
    (error > 0 ? hi : lo) = t;
    const double newton = s.speed > 1e-12 ? t - error / s.speed : 0.5 * (lo + hi);
    t = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
  }
  return t;
}

RunTimer::RunTimer(Emit emit, double tracePeriod, Sample sample)
    : emit_(std::move(emit)), tracePeriod_(tracePeriod), sample_(std::move(sample)) {}

void RunTimer::add(Segment&& segment, double entry, double exit, bool pinnedExit) {
  run_.emplace_back(std::move(segment), entry, exit);  // one move: no Member in between
  if (pinnedExit || run_.size() >= kLongestRun) flush();
}

void RunTimer::finish() { flush(); }

void RunTimer::flush() {
  if (!run_.empty()) time(0, run_.size());
  run_.clear();
}

void RunTimer::single(size_t k) {
  const Member& m = run_[k];
  const Segment& s = m.segment;
  if (changeDistance(m.entry, m.exit, s.dynamics) > s.length) {
    // A block cut out of a run in the middle of a longer change of speed: the change does not start and end
    // in it, so it passes with the acceleration it has, about constant over so short a block.
    const double time = 2.0 * s.length / (m.entry + m.exit);
    emit_(s, {m.entry, m.exit, std::max(m.entry, m.exit), std::min(m.entry, m.exit), time + s.restAfter});
    if (tracePeriod_ > 0.0) {
      const double a = (m.exit - m.entry) / time;
      for (double t = nextSample_; t < clock_ + time; t += tracePeriod_, nextSample_ = t) {
        const double dt = t - clock_;
        sample_(t, m.entry + a * dt, s.block.pointAt(m.entry * dt + 0.5 * a * dt * dt));
      }
    }
    clock_ += time + s.restAfter;
    return;
  }
  const BlockProfile p = blockProfile(s.length, m.entry, m.exit, s.cruise, s.dynamics);
  if (tracePeriod_ > 0.0) trace(p, s.dynamics, k, k + 1);
  emit_(s, {p.v0, p.v1, p.peak, std::min(p.v0, p.v1), p.time + s.restAfter});
  clock_ += p.time + s.restAfter;
}

void RunTimer::time(size_t first, size_t last) {
  if (last - first == 1) return single(first);
  double length = 0.0;
  Dynamics dynamics{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), false};
  for (size_t k = first; k < last; ++k) {
    length += run_[k].segment.length;
    dynamics = weakest(dynamics, run_[k].segment.dynamics);
  }
  const double v0 = run_[first].entry, v1 = run_[last - 1].exit;
  const double ceiling = reachableSpeed(std::max(v0, v1), length, dynamics);  // no block limit yet
  const BlockProfile p = blockProfile(length, v0, v1, ceiling, dynamics);
  // The first block whose limits the profile passes: its own cruise, or the junction it starts at.
  const double peakFrom = changeDistance(v0, p.peak, dynamics);
  double offset = 0.0;
  for (size_t k = first; k < last; ++k) {
    const Segment& s = run_[k].segment;
    // Nothing on the profile is faster than its peak: most blocks are checked without solving for a time.
    if (p.peak <= s.cruise * (1 + kSlack) && (k == first || p.peak <= s.junction * (1 + kSlack))) {
      offset += s.length;
      continue;
    }
    const double inside = std::clamp(peakFrom, offset, offset + s.length);
    const double highest = stateAt(p, timeAtDistance(p, inside, dynamics), dynamics).speed;
    const bool overJunction =
        k > first && stateAt(p, timeAtDistance(p, offset, dynamics), dynamics).speed > s.junction * (1 + kSlack);
    if (highest > s.cruise * (1 + kSlack) || overJunction) {
      // Cut around block k: the runs before and after keep their junction speeds, k goes on its own.
      if (k > first) time(first, k);
      single(k);
      if (k + 1 < last) time(k + 1, last);
      return;
    }
    offset += s.length;
  }
  emitFrom(p, dynamics, first, last);
}

void RunTimer::emitFrom(const BlockProfile& p, const Dynamics& d, size_t first, size_t last) {
  if (tracePeriod_ > 0.0) trace(p, d, first, last);
  double offset = 0.0, before = 0.0, entry = p.v0;
  const double peakFrom = changeDistance(p.v0, p.peak, d);
  for (size_t k = first; k < last; ++k) {
    const Segment& s = run_[k].segment;
    const double end = offset + s.length;
    const double after = k + 1 == last ? p.time : timeAtDistance(p, end, d, before, offset, entry);
    const double exit = k + 1 == last ? p.v1 : stateAt(p, after, d).speed;
    // The speed rises to the peak at peakFrom and never rises again: a block's fastest point is its exit
    // before it, its entry after it, the peak across it.
    const double peak = end <= peakFrom ? exit : offset >= peakFrom ? entry : p.peak;
    emit_(s, {entry, exit, std::max({peak, entry, exit}), std::min(entry, exit), after - before + s.restAfter});
    clock_ += s.restAfter;
    offset = end;
    before = after;
    entry = exit;
  }
  clock_ += p.time;
}

void RunTimer::trace(const BlockProfile& p, const Dynamics& d, size_t first, size_t last) {
  size_t k = first;
  double offset = 0.0;
  for (double t = nextSample_; t < clock_ + p.time; t += tracePeriod_) {
    const ProfileState state = stateAt(p, t - clock_, d);
    while (k + 1 < last && state.distance > offset + run_[k].segment.length) offset += run_[k++].segment.length;
    sample_(t, state.speed, run_[k].segment.block.pointAt(state.distance - offset));
    nextSample_ = t + tracePeriod_;
  }
}

}  // namespace hsm::kinematics::detail
