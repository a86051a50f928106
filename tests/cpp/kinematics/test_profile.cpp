#include "kinematics/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace hsm::kinematics;

namespace {
const Dynamics kJerk{2500.0, 5000.0, true};    // Mikron X: A²/J = 1250 mm/s (75 m/min)
const Dynamics kBrisk{2500.0, 5000.0, false};
}  // namespace

TEST(Profile, ChangeTimesFollowTheClosedForms) {
  EXPECT_NEAR(changeTime(0, 100, kJerk), 2.0 * std::sqrt(100.0 / 5000.0), 1e-12);   // jerk-limited
  EXPECT_NEAR(changeTime(0, 2000, kJerk), 2000.0 / 2500.0 + 2500.0 / 5000.0, 1e-12);  // reaches A
  EXPECT_NEAR(changeTime(100, 0, kBrisk), 100.0 / 2500.0, 1e-12);
  EXPECT_NEAR(changeDistance(20, 80, kJerk), 50.0 * changeTime(20, 80, kJerk), 1e-12);
}

TEST(Profile, ReachableSpeedInvertsChangeDistance) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> speed(0.0, 3000.0), distance(1e-4, 500.0);
  for (const Dynamics& d : {kJerk, kBrisk}) {
    for (int i = 0; i < 2000; ++i) {
      const double v0 = speed(random), s = distance(random);
      const double v1 = reachableSpeed(v0, s, d);
      ASSERT_GT(v1, v0);
      ASSERT_NEAR(changeDistance(v0, v1, d), s, 1e-8 * (1 + s)) << v0 << " " << s;
    }
  }
}

TEST(Profile, LongLineRestToRest) {
  const double length = 200.0, v = 100.0;  // 6 m/min
  EXPECT_NEAR(blockProfile(length, 0, 0, v, kJerk).time, length / v + 2.0 * std::sqrt(v / kJerk.jerk), 1e-12);
  EXPECT_NEAR(blockProfile(length, 0, 0, v, kBrisk).time, length / v + v / kBrisk.acceleration, 1e-12);
}

TEST(Profile, ShortBlockPeaksBelowCruise) {
  for (const Dynamics& d : {kJerk, kBrisk}) {
    const BlockProfile p = blockProfile(2.0, 10.0, 20.0, 500.0, d);
    EXPECT_LT(p.peak, 500.0);
    EXPECT_GE(p.peak, 20.0);
    EXPECT_NEAR(changeDistance(10, p.peak, d) + changeDistance(p.peak, 20, d), 2.0, 1e-6);
    EXPECT_NEAR(p.cruiseTime, 0.0, 1e-8);
  }
}

// Over many short jerk-limited blocks (the case whose peak is searched), the peak found is the one a bisection to
// the last bit finds, within the search's tolerance of 1e-9 (1 + cruise) mm/s, and the times add up.
TEST(Profile, SearchedPeaksAreTheBisectionsPeak) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const Dynamics d{500.0 + 9500.0 * unit(random), 1000.0 + 2e5 * unit(random), true};
    const double cruise = 50.0 + 950.0 * unit(random), v0 = cruise * unit(random), v1 = cruise * unit(random);
    const double length = std::abs(changeDistance(v0, v1, d)) + 0.001 + 5.0 * unit(random);
    const BlockProfile p = blockProfile(length, v0, v1, cruise, d);
    double lo = std::max(v0, v1), hi = cruise;
    if (changeDistance(v0, hi, d) + changeDistance(hi, v1, d) <= length) lo = hi;
    for (int k = 0; k < 200 && hi > lo; ++k) {
      const double mid = 0.5 * (lo + hi);
      (changeDistance(v0, mid, d) + changeDistance(mid, v1, d) > length ? hi : lo) = mid;
    }
    ASSERT_NEAR(p.peak, lo, 2e-9 * (1.0 + cruise)) << i;
    ASSERT_NEAR(p.accelTime + p.cruiseTime + p.decelTime, p.time, 1e-12);
  }
}

TEST(Profile, StateAtWalksTheWholeBlock) {
  for (const Dynamics& d : {kJerk, kBrisk}) {
    const BlockProfile p = blockProfile(30.0, 5.0, 12.0, 80.0, d);
    const ProfileState end = stateAt(p, p.time, d);
    EXPECT_NEAR(end.distance, 30.0, 1e-6);
    EXPECT_NEAR(end.speed, 12.0, 1e-6);
    double last = -1.0;
    for (int i = 0; i <= 1000; ++i) {
      const ProfileState s = stateAt(p, p.time * i / 1000.0, d);
      EXPECT_GE(s.distance, last - 1e-12);
      EXPECT_LE(s.speed, p.peak + 1e-9);
      last = s.distance;
    }
  }
}
