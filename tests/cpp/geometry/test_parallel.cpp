// parallelLanes: what the material removal relies on to cut rows without locks. Every step of every lane runs
// once, a lane's steps in order and never two of one lane at once, whatever the threads and the group of steps
// a thread keeps a lane for; the progress reported never goes back; a cancel from the report stops the lanes.
#include "common/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

using hsm::parallelLanes;

namespace {
struct LaneLog {
  std::vector<long> steps;        // in the order they ran
  std::atomic<int> running{0};    // steps of this lane running now
  std::atomic<int> overlaps{0};   // times a step started while another of the lane ran
};
}  // namespace

TEST(ParallelLanes, EveryStepOnceInOrderAndNeverTwoOfALaneAtOnce) {
  const int lanes = 8;
  const long steps = 300;
  for (int threads : {1, 2, 7})
    for (long group : {1L, 5L, 64L, 1000L}) {
      std::vector<LaneLog> logs(lanes);
      std::vector<long> reported;
      parallelLanes(
          lanes, threads, steps,
          [&](int lane, long step) {
            LaneLog& log = logs[static_cast<size_t>(lane)];
            if (log.running.fetch_add(1) != 0) ++log.overlaps;
            log.steps.push_back(step);
            volatile double sink = 0.0;  // a little work, so that threads do overlap
            for (int k = 0; k < 200; ++k) sink = sink + k * 1e-3;
            log.running.fetch_sub(1);
          },
          [&](long done) { reported.push_back(done); }, group);
      for (int lane = 0; lane < lanes; ++lane) {
        const LaneLog& log = logs[static_cast<size_t>(lane)];
        ASSERT_EQ(log.steps.size(), static_cast<size_t>(steps)) << "lane " << lane << ", " << threads << " threads, group " << group;
        for (long k = 0; k < steps; ++k) EXPECT_EQ(log.steps[static_cast<size_t>(k)], k) << "lane " << lane;
        EXPECT_EQ(log.overlaps.load(), 0) << "lane " << lane << ", " << threads << " threads, group " << group;
      }
      ASSERT_FALSE(reported.empty());
      EXPECT_EQ(reported.back(), steps) << threads << " threads, group " << group;
      for (size_t k = 1; k < reported.size(); ++k) EXPECT_LE(reported[k - 1], reported[k]);
    }
}

TEST(ParallelLanes, ACancelInTheReportStopsTheLanesEarly) {
  const int lanes = 8;
  const long steps = 20000;
  for (long group : {1L, 64L}) {
    std::atomic<long> ran{0};
    EXPECT_THROW(parallelLanes(
                     lanes, 2, steps,
                     [&](int, long) {
                       ++ran;
                       volatile double sink = 0.0;
                       for (int k = 0; k < 2000; ++k) sink = sink + k * 1e-3;
                     },
                     [&](long done) {
                       if (done > 0) throw std::runtime_error("cancelled");
                     },
                     group),
                 std::runtime_error);
    EXPECT_LT(ran.load(), lanes * steps) << "group " << group << ": every step ran despite the cancel";
  }
}
