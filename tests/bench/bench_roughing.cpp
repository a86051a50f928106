// 5-axis roughing part 1 on the paper's test part, the 7-blade impeller (issue 14's figures: stock − part
// < 2 s, each partition of a channel < 5 s, the setup search of S3 < 5 s, one core). Prints each step's time
// (best of `runs`), the counts and the check that the sub-volumes add up; the setup search on 1 and 2
// threads in the same run. Run: build/bin/bench_roughing [runs]
#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>

using namespace hsm::roughing;

namespace {
double bestOf(int runs, const std::function<void()>& work) {
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  PartAndStock wheel;
  const double build = bestOf(1, [&] { wheel = impeller(); });
  std::printf("impeller (7 blades) built in %.2f s\n", build);
  VolumeToRemove volume;
  const double cut = bestOf(runs, [&] { volume = volumeToRemove(wheel.stock, wheel.part); });
  std::printf("stock - part: %.2f s (best of %d; target < 2 s), %zu channels, %.1f mm3 (stock %.1f - part %.1f)%s\n",
              cut, runs, volume.solids.size(), volume.volume, volume.stockVolume, volume.partVolume,
              volume.fuzzyRetry ? ", fuzzy retry" : "");
  const RemovalSolid& channel = volume.solids.front();
  std::printf("channel 1: %.1f mm3, %d surfaces\n", channel.volume, channel.groupCount());
  for (Strategy strategy : {Strategy::PlanesParallelToFace, Strategy::CoaxialCylinders, Strategy::SetupPlanes,
                            Strategy::StockOffsets, Strategy::HubOffsets}) {
    Partition p;
    const double t = bestOf(runs, [&] { p = partition(channel, wheel.part, strategy); });
    std::printf("%-24s %5.2f s (target < 5 s)  %2zu sub-volumes, sum - volume = %.2e relative%s\n",
                strategyName(strategy).c_str(), t, p.subVolumes.size(), (p.volume - channel.volume) / channel.volume,
                strategy == Strategy::SetupPlanes ? "  (includes the setup search)" : "");
  }
  // The 5-axis slicings at finer steps (a Ø4 tool, half engagement): more surfaces for one splitter.
  for (double step : {4.0, 2.0})
    for (Strategy strategy : {Strategy::StockOffsets, Strategy::HubOffsets}) {
      Partition p;
      const double t = bestOf(1, [&] { p = partition(channel, wheel.part, strategy, {step}); });
      std::printf("%-24s step %.0f mm: %5.2f s  %2zu sub-volumes, sum - volume = %.2e relative\n",
                  strategyName(strategy).c_str(), step, t, p.subVolumes.size(), (p.volume - channel.volume) / channel.volume);
    }
  for (int threads : {1, 2}) {
    PartitionSettings settings;
    settings.threads = threads;
    std::pair<Eigen::Vector3d, double> found;
    const double t = bestOf(runs, [&] { found = setupDirection(channel, wheel.part, settings); });
    std::printf("setup search, %d thread%s: %.2f s (target < 5 s on one), direction (%.3f, %.3f, %.3f) reaches %.1f %%\n",
                threads, threads > 1 ? "s" : "", t, found.first.x(), found.first.y(), found.first.z(), 100.0 * found.second);
  }
  return 0;
}
