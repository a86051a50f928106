// Internal: timing of runs. Between two pinned junctions the machine follows one speed profile (up to a
// peak, cruise, down) across all the blocks of the run; each block's time is the time the profile spends
// on it. Where the run's profile would pass a block's own limit, the run is cut at that block and the
// pieces are timed on their own, from the junction speeds the planner fixed.
#pragma once

#include "kinematics/planner.hpp"

#include <functional>
#include <vector>

namespace hsm::kinematics::detail {

struct BlockTiming {
  double entry = 0.0, exit = 0.0, peak = 0.0, min = 0.0;  // mm/s
  double time = 0.0;                                       // s
};

class RunTimer {
public:
  using Emit = std::function<void(const Segment&, const BlockTiming&)>;
  // `sample(t, speed, point)` receives trace samples every `tracePeriod` seconds when that is > 0.
  using Sample = std::function<void(double t, double speed, const Eigen::Vector3d& point)>;
  RunTimer(Emit emit, double tracePeriod, Sample sample);

  void add(Segment&& segment, double entry, double exit, bool pinnedExit);
  void finish();

private:
  struct Member {
    Member(Segment&& s, double in, double out) : segment(std::move(s)), entry(in), exit(out) {}
    Segment segment;
    double entry, exit;
  };
  void flush();
  void time(size_t first, size_t last);
  void single(size_t k);
  void emitFrom(const BlockProfile& profile, const Dynamics& dynamics, size_t first, size_t last);
  void trace(const BlockProfile& profile, const Dynamics& dynamics, size_t first, size_t last);

  Emit emit_;
  double tracePeriod_;
  Sample sample_;
  std::vector<Member> run_;
  double clock_ = 0.0, nextSample_ = 0.0;
};

// Time at which a profile has covered `distance` (Newton on the distance, guarded by bisection).
// The time at which the profile has covered `distance`. A known earlier point (time `since`, at `speed`)
// starts Newton next to the answer: consecutive short blocks then cost one or two steps each.
double timeAtDistance(const BlockProfile& profile, double distance, const Dynamics& dynamics, double since = 0.0,
                      double sinceDistance = 0.0, double sinceSpeed = -1.0);

}  // namespace hsm::kinematics::detail
