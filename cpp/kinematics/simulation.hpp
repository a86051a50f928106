// Feed-rate simulation: what the machine really does on a program (guidance-curve paper §2.3).
//
// A MachineModel and a program in, a SimulationResult out. Blocks stream through a look-ahead planner of the
// machine's depth: per-axis limits projected on each block, curvature limits on arcs and on chains of short
// blocks, junction limits by controller (exact stop, velocity jumps, rounding within a tolerance, blend arcs,
// junction deviation), a backward pass that keeps the machine able to stop at the last block it sees and a
// forward pass as blocks are committed; each block's time comes from its jerk-limited (S-curve) or
// acceleration-limited (trapezoidal) profile. Memory does not grow with the program unless per-block
// results or a trace are asked for.
#pragma once

#include "kinematics/five_axis_motion.hpp"
#include "kinematics/gcode.hpp"
#include "kinematics/machine.hpp"
#include "kinematics/profile.hpp"

#include <array>
#include <functional>
#include <istream>
#include <vector>

namespace hsm::kinematics {

struct BlockResult {
  long line = 0;                   // source line
  Motion motion = Motion::Linear;
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  Eigen::Vector3d center = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();  // arcs
  double sweep = 0.0;              // arcs: signed angle about `normal`, radians (0 for lines)
  double length = 0.0;             // mm
  double programmedFeed = 0.0;     // mm/s (rapid: the rapid speed along the block)
  double entryFeed = 0.0, exitFeed = 0.0, peakFeed = 0.0;  // mm/s
  double minFeed = 0.0, meanFeed = 0.0;                    // mm/s; mean = length / time
  double startTime = 0.0, time = 0.0;                      // s
  // What held the speed down for most of the block's time (SpeedLimit: the feed, an axis, curvature, block rate).
  SpeedLimit limit = SpeedLimit::Feed;
  // Only rotary axes move (the tip may stay put): feeds are in deg/s of the rotary axes, and the block is left
  // out of the feed and length classes.
  bool rotaryOnly = false;
  // 4- and 5-axis machines: the rotary axes (chain order, deg) and X Y Z of the machine at both ends.
  Eigen::Vector2d rotaryStart = Eigen::Vector2d::Zero(), rotaryEnd = Eigen::Vector2d::Zero();
  Eigen::Vector3d machineStart = Eigen::Vector3d::Zero(), machineEnd = Eigen::Vector3d::Zero();
};

// The paper's five classes of reached feed against programmed feed: < 0.3, 0.3–0.5, 0.5–0.7, 0.7–0.9, ≥ 0.9.
inline constexpr std::array<double, 4> kFeedClassEdges{0.3, 0.5, 0.7, 0.9};
// Block-length classes, mm: < 0.1, 0.1–0.25, 0.25–0.5, 0.5–1, 1–2, 2–5, 5–10, ≥ 10.
inline constexpr std::array<double, 7> kLengthClassEdges{0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0};

struct FeedClasses {
  std::array<double, 5> blocks{}, length{}, time{};  // shares (0..1) of cutting blocks, length and time
};

struct SimulationSummary {
  std::string machine;
  double totalTime = 0.0, cuttingTime = 0.0, rapidTime = 0.0, dwellTime = 0.0;  // s
  double naiveTime = 0.0, naiveCuttingTime = 0.0;  // Σ length / programmed feed (rapids at rapid speed), s
  long blockCount = 0, cuttingBlocks = 0, rapidBlocks = 0;
  double cuttingLength = 0.0, rapidLength = 0.0;  // mm
  FeedClasses feedClasses;
  std::array<long, kLengthClassEdges.size() + 1> lengthClasses{};  // cutting blocks per length class
  ReaderStats reader;
  // Seconds during which each SpeedLimit held the speed (a piece that cruises: what set its cruise; one that
  // never reaches it: the axis whose acceleration bounds it). Indexed by SpeedLimit.
  std::array<double, kSpeedLimitCount> limitTime{};

  // Simulated time over the length/feed estimate of CAM systems (0 for an empty program).
  double timeOverNaive() const { return naiveTime > 0.0 ? totalTime / naiveTime : 0.0; }
};

struct TraceSample {
  double t, x, y, z, v;  // s, mm, mm/s
};

struct SimulationResult {
  SimulationSummary summary;
  std::vector<BlockResult> blocks;  // when SimulationOptions::keepBlocks
  std::vector<TraceSample> trace;   // when SimulationOptions::tracePeriod > 0
};

// A trace samples at most every kMinTracePeriod (a tenth of the fastest servo cycle), and keeps at most
// kMaxTraceSamples in memory (a sink, onTraceSample, takes any number).
inline constexpr double kMinTracePeriod = 1e-4;  // s
inline constexpr long kMaxTraceSamples = 5000000;

struct SimulationOptions {
  bool keepBlocks = false;
  double tracePeriod = 0.0;                               // s between trace samples; 0: no trace
  std::function<void(const BlockResult&)> onBlock;        // each block as it is committed (CSV output)
  std::function<void(const TraceSample&)> onTraceSample;  // trace samples as they come (not kept when set)
  std::function<void(long linesRead)> onProgress;         // called every 65536 blocks
};

SimulationResult simulate(std::istream& program, const MachineModel& machine, const ReaderOptions& reading = {},
                          const SimulationOptions& options = {});
// The program in the file at `path`, streamed; InputError when it cannot be read.
SimulationResult simulateFile(const std::string& path, const MachineModel& machine, const ReaderOptions& reading = {},
                              const SimulationOptions& options = {});
SimulationResult simulateBlocks(const std::vector<Block>& blocks, const MachineModel& machine,
                                const SimulationOptions& options = {});

}  // namespace hsm::kinematics
