#include "kinematics/simulation.hpp"

#include "common/text.hpp"

#include "kinematics/merging.hpp"
#include "kinematics/planner.hpp"
#include "kinematics/runs.hpp"

#include <algorithm>
#include <fstream>
#include <cmath>
#include <limits>

namespace hsm::kinematics {

namespace {

int feedClass(double ratio) {
  int k = 0;
  while (k < static_cast<int>(kFeedClassEdges.size()) && ratio >= kFeedClassEdges[k] - 1e-9) ++k;
  return k;
}

int lengthClass(double length) {
  int k = 0;
  while (k < static_cast<int>(kLengthClassEdges.size()) && length >= kLengthClassEdges[k]) ++k;
  return k;
}

// Collects committed segments into program blocks (grbl cuts arcs into several segments), the summary,
// and what the options ask for.
class Collector {
public:
  Collector(const MachineModel& machine, const SimulationOptions& options, SimulationResult& result)
      : machine_(machine), options_(options), result_(result) {
    result_.summary.machine = machine.name;
  }

  void commit(const detail::Segment& s, const detail::BlockTiming& p) {
    if (s.source != currentSource_) flush();
    const int label = static_cast<int>(limitOf(s, p));
    if (!open_) {
      blockLimit_ = label;
      mixedLimits_ = false;
      open_ = true;
      currentSource_ = s.source;
      current_ = BlockResult{};
      current_.line = s.block.line;
      current_.motion = s.block.motion;
      current_.start = s.blendArc ? s.programmedStart : s.block.start;
      current_.center = s.block.center;
      current_.normal = s.block.normal;
      current_.sweep = s.block.isArc() ? s.block.sweep : 0.0;
      current_.programmedFeed = s.programmed;
      current_.entryFeed = p.entry;
      current_.minFeed = p.min;
      current_.startTime = clock_;
      if (s.joint) {
        current_.rotaryOnly = s.joint->rotaryOnly;
        current_.machineStart = s.joint->start.head<3>();
        current_.rotaryStart = s.joint->start.tail<2>();
      } else {
        fixedAngles(s.block, current_.start, current_.machineStart, current_.rotaryStart);
      }
      naive_ = 0.0;
    }
    if (label != blockLimit_ && !mixedLimits_) {  // a block of pieces held by different limits: weigh them
      mixedLimits_ = true;
      limitTimes_.fill(0.0);
      limitTimes_[blockLimit_] = current_.time;
    }
    if (mixedLimits_) limitTimes_[label] += p.time;
    result_.summary.limitTime[label] += p.time;
    current_.end = s.blendArc ? s.programmedEnd : s.block.end;  // the block's end, not its blend arc's
    if (s.joint) {
      current_.machineEnd = s.joint->end.head<3>();
      current_.rotaryEnd = s.joint->end.tail<2>();
    } else {
      fixedAngles(s.block, current_.end, current_.machineEnd, current_.rotaryEnd);
    }
    current_.length += s.joint ? s.joint->tipLength : s.length;
    current_.exitFeed = p.exit;
    current_.peakFeed = std::max(current_.peakFeed, p.peak);
    current_.minFeed = std::min(current_.minFeed, p.min);
    current_.time += p.time;
    naive_ += s.length / s.programmed;
    clock_ += p.time;
  }

  void flush() {
    if (!open_) return;
    open_ = false;
    BlockResult& b = current_;
    if (!std::isfinite(b.time) || b.time < 0.0 || !std::isfinite(b.length))
      throw ComputationError("line " + std::to_string(b.line) + ": the simulated time of the block is not a finite "
                             "number (length " + mm(b.length) + "); check its coordinates and the machine's limits");
    b.meanFeed = b.time > 0.0 ? b.length / b.time : 0.0;
    b.limit = static_cast<SpeedLimit>(
        mixedLimits_ ? std::max_element(limitTimes_.begin(), limitTimes_.end()) - limitTimes_.begin() : blockLimit_);
    SimulationSummary& sum = result_.summary;
    ++sum.blockCount;
    sum.totalTime += b.time;
    sum.naiveTime += naive_;
    if (b.motion == Motion::Rapid) {
      ++sum.rapidBlocks;
      sum.rapidTime += b.time;
      sum.rapidLength += b.length;
    } else {
      ++sum.cuttingBlocks;
      sum.cuttingTime += b.time;
      sum.cuttingLength += b.length;
      sum.naiveCuttingTime += naive_;
    }
    if (b.motion != Motion::Rapid && !b.rotaryOnly) {
      const int k = feedClass(b.programmedFeed > 0.0 ? b.meanFeed / b.programmedFeed : 0.0);
      sum.feedClasses.blocks[k] += 1.0;
      sum.feedClasses.length[k] += b.length;
      sum.feedClasses.time[k] += b.time;
      ++sum.lengthClasses[lengthClass(b.length)];
      ++classified_;
      classifiedTime_ += b.time;
    }
    if (options_.onBlock) options_.onBlock(b);
    if (options_.keepBlocks) result_.blocks.push_back(b);
    if (options_.onProgress && (sum.blockCount & 0xFFFF) == 0) options_.onProgress(b.line);
  }

  void sample(double t, double speed, const Eigen::Vector3d& x) {
    const TraceSample sample{t, x.x(), x.y(), x.z(), speed};
    if (options_.onTraceSample) {
      options_.onTraceSample(sample);
      return;
    }
    if (static_cast<long>(result_.trace.size()) >= kMaxTraceSamples)
      throw InputError("the trace reached " + std::to_string(kMaxTraceSamples) + " samples at t = " + number(t) +
                       " s: use a trace period of at least " + number(std::max(10.0 * options_.tracePeriod, 1e-3)) +
                       " s, or write the trace to a file as it comes");
    result_.trace.push_back(sample);
  }

  void finish(const ReaderStats& reader) {
    flush();
    SimulationSummary& sum = result_.summary;
    sum.reader = reader;
    sum.dwellTime = reader.dwellTime;
    sum.totalTime += reader.dwellTime;
    sum.naiveTime += reader.dwellTime;
    FeedClasses& fc = sum.feedClasses;
    for (int k = 0; k < 5; ++k) {
      if (classified_ > 0) fc.blocks[k] /= double(classified_);
      if (sum.cuttingLength > 0) fc.length[k] /= sum.cuttingLength;
      if (classifiedTime_ > 0) fc.time[k] /= classifiedTime_;
    }
  }

private:
  const MachineModel& machine_;
  const SimulationOptions& options_;
  SimulationResult& result_;
  BlockResult current_;
  std::array<double, kSpeedLimitCount> limitTimes_{};
  int blockLimit_ = 0;
  long classified_ = 0;          // cutting blocks in the feed classes (not those turning rotary axes only)
  double classifiedTime_ = 0.0;
  bool mixedLimits_ = false;
  bool open_ = false;

  // A block planned as a 3-axis one at `point` of the program: X Y Z of the machine, and on a 4- or 5-axis
  // program (LinuxCNC's planner: the rotary axes stay where the program left them) the angles, the machine's
  // X Y Z where the program gives the tip, and the tip (`point` becomes it) where it gives the machine's axes.
  void fixedAngles(const Block& b, Eigen::Vector3d& point, Eigen::Vector3d& linear, Eigen::Vector2d& rotary) const {
    linear = point;
    if (!b.rotary || !machine_.hasRotaryAxes()) return;
    RotaryAngles angles{0.0, 0.0};
    for (size_t i = 0; i < machine_.rotaryAxes.size(); ++i) angles[i] = b.rotaryEnd[machine_.rotaryAxes[i].name - 'A'];
    rotary = {angles[0], angles[1]};
    if (b.toolTip || machine_.toolTipProgrammed)
      linear = linearAxesFor(machine_, point, angles);
    else
      point = forwardKinematics(machine_, {linear, angles}).tip;
  }

  // What held a piece's speed: what set its cruise if it reached it, else the axis whose acceleration bounds it.
  SpeedLimit limitOf(const detail::Segment& s, const detail::BlockTiming& p) const {
    if (p.peak >= 0.95 * s.cruise) return s.limit;
    if (s.joint) return s.accelerationLimit;
    int slowest = 0;
    double least = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const double u = std::abs(s.startTangent[i]);
      if (u > 1e-12 && machine_.maxAcceleration[i] / u < least) {
        least = machine_.maxAcceleration[i] / u;
        slowest = i;
      }
    }
    return static_cast<SpeedLimit>(static_cast<int>(SpeedLimit::X) + slowest);
  }
  long currentSource_ = -1;
  double clock_ = 0.0, naive_ = 0.0;
};

// grbl executes arcs as chords within its arc tolerance; the other controllers interpolate them. Blocks of
// 4- and 5-axis programs go to the planner in pieces with their axes' motion (five_axis_motion.hpp).
template <class Sink>
void feed(detail::Planner& planner, const MachineModel& machine, const Block& block, long source,
          FiveAxisCutter& cutter, Sink&&) {
  // LinuxCNC plans a block that leaves the rotary axes where they are as a 3-axis block of the program.
  if (block.rotary && (machine.rotaryPlanner != RotaryPlanner::LinuxCnc || cutter.turns(block))) {
    cutter.cut(block, [&](const Block& piece, const JointMotion& joint) { planner.add(piece, source, &joint); });
    return;
  }
  if (block.inverseTime) {  // G93 on a 3-axis block: the block lasts 1/F
    Block timed = block;
    timed.feed = block.length() * block.feed;
    timed.inverseTime = false;
    return feed(planner, machine, timed, source, cutter, 0);
  }
  if (machine.controller != ControllerKind::Grbl || !block.isArc()) {
    planner.add(block, source);
    return;
  }
  const double r = block.radius, tol = std::min(machine.arcTolerance, 0.5 * r);
  const double step = 2.0 * std::acos(1.0 - tol / r);
  // At most 100,000 chords: an arc of absurd radius is bounded work too.
  const int pieces = std::clamp(static_cast<int>(std::min(1e5, std::ceil(std::abs(block.sweep) / step))), 1, 100000);
  const double length = block.length();
  Eigen::Vector3d from = block.start;
  for (int i = 1; i <= pieces; ++i) {
    Block chord = block;
    chord.motion = Motion::Linear;
    chord.start = from;
    chord.end = i == pieces ? block.end : block.pointAt(length * i / pieces);
    planner.add(chord, source);
    from = chord.end;
  }
}

template <class Next>
SimulationResult run(const MachineModel& machine, const SimulationOptions& options, Next&& next,
                     const std::function<ReaderStats()>& stats) {
  checkMachine(machine);
  if (!(options.tracePeriod == 0.0 || (options.tracePeriod >= kMinTracePeriod && options.tracePeriod <= 3600.0)))
    throw InputError("trace period " + number(options.tracePeriod) + " s must be 0 (no trace) or between " +
                     number(kMinTracePeriod) + " s and 1 h, e.g. 0.001 s (LinuxCNC's servo cycle)");
  SimulationResult result;
  Collector collector(machine, options, result);
  detail::RunTimer runs([&](const detail::Segment& s, const detail::BlockTiming& t) { collector.commit(s, t); },
                        options.tracePeriod,
                        [&](double t, double v, const Eigen::Vector3d& x) { collector.sample(t, v, x); });
  detail::Planner planner(machine, [&](detail::Segment&& s, double entry, double exit, bool pinned) {
    runs.add(std::move(s), entry, exit, pinned);
  });
  long source = 0;
  FiveAxisCutter cutter(machine);
  BlockMerger merger(machine, [&](const Block& b) { feed(planner, machine, b, source++, cutter, 0); });
  Block block;
  while (next(block)) merger.add(block);
  merger.finish();
  planner.finish();
  runs.finish();
  collector.finish(stats());
  return result;
}

}  // namespace

SimulationResult simulate(std::istream& program, const MachineModel& machine, const ReaderOptions& reading,
                          const SimulationOptions& options) {
  ReaderOptions language = reading;
  language.conventions = machine.conventions;
  GcodeReader reader(program, language);
  return run(machine, options, [&](Block& b) { return reader.next(b); }, [&] { return reader.stats(); });
}

SimulationResult simulateFile(const std::string& path, const MachineModel& machine, const ReaderOptions& reading,
                              const SimulationOptions& options) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError("cannot read the program '" + printable(path) + "': check the path");
  ReaderOptions beside = reading;  // its subroutine files beside it first, as LinuxCNC's program folder
  const size_t slash = path.find_last_of('/');
  beside.subroutineFolders.insert(beside.subroutineFolders.begin(), slash == std::string::npos ? "." : path.substr(0, slash));
  return simulate(stream, machine, beside, options);
}

SimulationResult simulateBlocks(const std::vector<Block>& blocks, const MachineModel& machine,
                                const SimulationOptions& options) {
  size_t i = 0;
  return run(
      machine, options,
      [&](Block& b) {
        if (i == blocks.size()) return false;
        b = blocks[i++];
        return true;
      },
      [&] {
        ReaderStats stats;
        stats.motionBlocks = static_cast<long>(blocks.size());
        return stats;
      });
}

}  // namespace hsm::kinematics
