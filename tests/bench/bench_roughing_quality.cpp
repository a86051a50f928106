// What each roughing strategy leaves on the paper's impeller, and what it costs: per strategy, every channel
// partitioned and swept (the sweep's own time), joined, its material removal simulated (V_r with and without
// the allowance layer, feed path, in-material share).
// Run: build/bin/bench_roughing_quality [resolution mm] [strategies, e.g. 135] [key=value …]
//   keys: push (mm a boundary may move to the exact clearance; 0: off), step_up_min, step_up_scallop (mm; step_up_min=0: no intermediate levels), threads, split (the grid of
//   the split of what is left, mm; 0: none), diameter and corner (the torus, mm), holder (its diameter, mm), step (the partition's, mm).
#include "roughing/clearance.hpp"
#include "roughing/parts.hpp"
#include "roughing/reach.hpp"
#include "roughing/removal.hpp"
#include "roughing/roughing.hpp"
#include "roughing/sweep.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

using namespace hsm::roughing;

namespace {
double seconds(const std::chrono::steady_clock::time_point& since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}
}  // namespace

int main(int argc, char** argv) {
  const double resolution = argc > 1 ? std::atof(argv[1]) : 0.4;
  const std::string which = argc > 2 ? argv[2] : "12345";
  std::map<std::string, double> options;
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    if (eq != std::string::npos) options[a.substr(0, eq)] = std::atof(a.c_str() + eq + 1);
  }
  SweepSettings settings;
  if (options.count("step_up_min")) settings.stepUpMinimum = options["step_up_min"];
  if (options.count("step_up_scallop")) settings.stepUpScallop = options["step_up_scallop"];
  if (options.count("push")) settings.pushOutMost = options["push"];
  if (options.count("diameter")) settings.cutter.diameter = options["diameter"];
  if (options.count("corner")) settings.cutter.cornerRadius = options["corner"];
  if (options.count("holder")) settings.cutter.holderDiameter = options["holder"];
  PartitionSettings partitionSettings;
  if (options.count("step")) partitionSettings.step = options["step"];
  RemovalSettings removalSettings;
  removalSettings.resolution = resolution;
  if (options.count("threads")) removalSettings.threads = static_cast<int>(options["threads"]);

  const PartAndStock wheel = impeller();
  const VolumeToRemove volume = volumeToRemove(wheel.stock, wheel.part);
  for (char c : which) {
    const Strategy strategy = static_cast<Strategy>(c - '0');
    auto start = std::chrono::steady_clock::now();
    std::vector<Partition> partitions;
    for (const RemovalSolid& solid : volume.solids) partitions.push_back(partition(solid, wheel.part, strategy, partitionSettings));
    const double partitioned = seconds(start);
    start = std::chrono::steady_clock::now();
    std::vector<std::vector<ToolMove>> regions;
    std::vector<LeftSplit> splits;
    std::vector<std::pair<std::vector<Eigen::Vector3d>, std::vector<Eigen::Vector3d>>> ringZero;
    size_t passes = 0, intermediate = 0, open = 0;
    double cutting = 0.0, ramping = 0.0, linking = 0.0, rapid = 0.0;
    int retracts = 0, ramps = 0, plunges = 0;
    for (size_t i = 0; i < partitions.size(); ++i) {
      SweepResult r = sweep(partitions[i], volume.solids[i], wheel.part, wheel.stock, settings);
      passes += r.passes.size();
      for (const Pass& p : r.passes)
        if (p.ring == 0) {
          std::vector<Eigen::Vector3d> axes;
          for (const Eigen::Vector3d& q : p.points) {
            size_t best = 0;  // the move nearest the point gives its axis
            for (size_t m = 0; m < r.moves.size(); ++m)
              if ((r.moves[m].tip - q).squaredNorm() < (r.moves[best].tip - q).squaredNorm()) best = m;
            axes.push_back(r.moves[best].axis);
          }
          ringZero.emplace_back(p.points, axes);
        }
      for (const Pass& p : r.passes) intermediate += p.intermediate, open += !p.closed;
      cutting += r.cuttingLength, ramping += r.rampLength, linking += r.linkLength, rapid += r.rapidLength;
      retracts += r.retracts, ramps += r.ramps, plunges += r.plunges;
      regions.push_back(std::move(r.moves));
    }
    const double swept = seconds(start);
    {  // How near the part the cuts run: a domain that keeps the tool farther than the allowance leaves stock.
      const auto checkStart = std::chrono::steady_clock::now();
      const ClearanceChecker checker(wheel.part, 0.01);
      const double edges[] = {0.49, 0.55, 0.7, 1.0, 1.5, 2.0, 2.5};
      long counts[8] = {0};
      double least = 1e9;
      for (const auto& moves : regions) {
        const ClearanceReport c = checker.check(moves, settings.cutter, settings.allowance - 0.01, 1.0);
        least = std::min(least, c.minimum);
      }
      std::printf("S%c independent clearance check of the whole path: %.1f s\n", c, seconds(checkStart));
      // The outer passes of every level: where a level's domain is the part's keep-out, their distance says how
      // much room it left.
      for (const auto& passes : ringZero) {
        std::vector<ToolMove> along;
        for (const Eigen::Vector3d& p : passes.first) along.push_back({MoveKind::Cut, p, Eigen::Vector3d::UnitZ(), 0});
        for (size_t m = 0; m < along.size(); ++m) along[m].axis = passes.second[m];
        const ClearanceReport c = checker.check(along, settings.cutter, settings.allowance - 0.01, 1.0);
        for (size_t m = 1; m < along.size(); ++m) {
          int b = 0;
          while (b < 7 && c.moveMinimum[m] >= edges[b]) ++b;
          ++counts[b];
        }
      }
      std::printf("S%c outer passes' points by their least distance to the part (whole path's closest %.3f mm): <0.49 %ld, <0.55 %ld, <0.7 %ld, <1 %ld, "
                  "<1.5 %ld, <2 %ld, <2.5 %ld, farther %ld\n", c, least, counts[0], counts[1], counts[2], counts[3],
                  counts[4], counts[5], counts[6], counts[7]);
    }
    const double splitGrid = options.count("split") ? options["split"] : 0.4;
    start = std::chrono::steady_clock::now();
    if (splitGrid > 0.0)
      for (size_t i = 0; i < partitions.size(); ++i)
        splits.push_back(splitWhatIsLeft(partitions[i], volume.solids[i], wheel.part, settings.cutter, settings.allowance,
                                         regions[i], splitGrid, removalSettings.threads));
    const double splitTime = seconds(start);
    std::printf("S%c sweep: %zu passes (%zu on intermediate levels, %zu open), cut %.0f mm, ramps and plunges %.0f mm "
                "(%d ramps, %d plunges), links %.0f mm, rapids %.0f mm (%d retracts)\n", c, passes, intermediate, open,
                cutting, ramping, ramps, plunges, linking, rapid, retracts);
    const std::vector<ToolMove> moves = joinSweeps(regions, wheel.stock);
    start = std::chrono::steady_clock::now();
    const RemovalResult r = simulateRemoval(moves, settings.cutter, wheel.stock, wheel.part, removalSettings);
    const double removed = seconds(start);
    std::printf("S%c: partition %.1f s, sweep %.1f s (%zu passes, %.0f mm cut), removal %.1f s at %.2f mm: V_r %.1f %% "
                "(beyond the allowance %.1f %%), path %.0f mm, feed %.0f mm, in material %.1f %% of feed, %.1f %% of path, "
                "stick-out %.1f, gouge %.3f mm3, rapid faults %zu\n",
                c, partitioned, swept, passes, cutting, removed, resolution, r.remainingShare, r.beyondAllowanceShare,
                r.pathLength, r.feedLength, r.inMaterialShare, r.inMaterialPathShare, r.stickOut, r.gougeVolume,
                r.rapidFaults.size());
    if (!splits.empty()) {
      LeftSplit total;
      std::string perChannel;
      for (const LeftSplit& split : splits) {
        total.volume += split.volume, total.unreachable += split.unreachable, total.betweenLevels += split.betweenLevels;
        char text[96];
        std::snprintf(text, sizeof text, " %.1f/%.1f", 100.0 * split.unreachable / split.volume,
                      100.0 * split.betweenLevels / split.volume);
        perChannel += text;
      }
      const double u = 100.0 * total.unreachable / r.volumeToRemove, b = 100.0 * total.betweenLevels / r.volumeToRemove;
      std::printf("S%c split at %.2f mm (%.1f s): sampled %.0f mm3 of %.0f; unreachable %.1f %% (beyond the allowance "
                  "layer %.1f), between levels %.1f %%, left by the path at its levels %.1f %%; per channel%s\n",
                  c, splitGrid, splitTime, total.volume, r.volumeToRemove, u,
                  u - (r.remainingShare - r.beyondAllowanceShare), b, r.remainingShare - u - b, perChannel.c_str());
    }
    std::fflush(stdout);
  }
  return 0;
}
