// 5-axis roughing on the paper's test part, the 7-blade impeller. Part 1 (stock − part
// < 2 s, each partition of a channel < 5 s, the setup search of S3 < 5 s, one core): each step's time (best of
// `runs`), the counts and the check that the sub-volumes add up; the setup search on 1 and 2 threads in the
// same run. Part 2 (one strategy's toolpaths on the impeller < 10 s): the sweeps (S1-S5) of every
// channel, and the 2-D offsets of one level by Clipper and by OCCT's BRepOffsetAPI_MakeOffset.
// Part 3: material removal of each strategy on the whole impeller, 1 and 2 threads.
// Run: build/bin/bench_roughing [runs] [removal [S1..S5|all] [threads]]   ("removal": part 3 only, the best
// of `runs` of each simulation, of one strategy and on one thread count when named). Under `valgrind
// --tool=cachegrind --cache-sim=no --instr-at-start=no` (or callgrind with --instr-atstart=no) only the
// simulations are instrumented: the I refs are their instructions (e.g. `... 1 removal S3 1`).
#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"
#include "roughing/clearance.hpp"
#include "roughing/removal.hpp"
#include <string>
#include "roughing/sweep.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepOffsetAPI_MakeOffset.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <polyclipping/clipper.hpp>
#if __has_include(<valgrind/callgrind.h>) && __has_include(<valgrind/cachegrind.h>)
#include <valgrind/cachegrind.h>
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CACHEGRIND_START_INSTRUMENTATION
#define CACHEGRIND_STOP_INSTRUMENTATION
#endif
#include <ctime>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <thread>

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

// CPU seconds of the whole process (all its threads): what the work costs whatever else runs on the machine.
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
}  // namespace

// Part 2: S1 to S5 swept on every channel (partitions not counted), one core.
void sweeps(const PartAndStock& wheel, const VolumeToRemove& volume, int runs) {
  for (Strategy strategy : {Strategy::PlanesParallelToFace, Strategy::CoaxialCylinders, Strategy::SetupPlanes,
                            Strategy::StockOffsets, Strategy::HubOffsets}) {
    std::vector<Partition> partitions;
    for (const RemovalSolid& solid : volume.solids) partitions.push_back(partition(solid, wheel.part, strategy));
    size_t moves = 0, passes = 0;
    double length = 0.0;
    const double t = bestOf(runs, [&] {
      moves = passes = 0;
      length = 0.0;
      for (size_t i = 0; i < partitions.size(); ++i) {
        const SweepResult r = sweep(partitions[i], volume.solids[i], wheel.part, wheel.stock, {});
        moves += r.moves.size();
        passes += r.passes.size();
        length += r.cuttingLength + r.rampLength + r.linkLength;
      }
    });
    std::printf("sweep %-22s %5.2f s for %zu channels (target < 10 s): %zu passes, %zu moves, %.0f mm of cutting path\n",
                strategyName(strategy).c_str(), t, partitions.size(), passes, moves, length);
    // The independent clearance check of the whole strategy, every 1 mm of every move.
    std::vector<SweepResult> results;
    for (size_t i = 0; i < partitions.size(); ++i)
      results.push_back(sweep(partitions[i], volume.solids[i], wheel.part, wheel.stock, {}));
    long positions = 0, tooClose = 0;
    double least = 1e300;
    const SweepSettings defaults;
    std::unique_ptr<ClearanceChecker> prepared;
    const double meshing = bestOf(1, [&] { prepared = std::make_unique<ClearanceChecker>(wheel.part); });
    const double check = meshing + bestOf(1, [&] {
      const ClearanceChecker& checker = *prepared;
      for (const SweepResult& r : results) {
        const ClearanceReport c = checker.check(r.moves, defaults.cutter, defaults.allowance - 0.01, 1.0);
        positions += c.positions;
        tooClose += c.tooClose;
        least = std::min(least, c.minimum);
      }
    });
    std::printf("  clearance check %.2f s (target < 10 s; the part's mesh and grid %.2f s of it): %ld positions every 1 mm, "
                "closest %.3f mm (allowance %.2f), %ld closer than allowance - 0.01\n", check, meshing, positions, least,
                defaults.allowance, tooClose);
  }
}

// Part 2: contour-parallel offsets of one planar section of the channel every 5.6 mm inwards until nothing is
// left, by Clipper (the wires as polygons within 0.01 mm) and by OCCT's planar offset of the face.
void offsets(const RemovalSolid& channel) {
  Bnd_Box box;
  BRepBndLib::Add(channel.solid, box);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const gp_Pln plane(gp_Pnt(0, 0, 0.5 * (z0 + z1)), gp_Dir(0, 0, 1));
  const TopoDS_Shape section = BRepAlgoAPI_Common(channel.solid, BRepBuilderAPI_MakeFace(plane, -500, 500, -500, 500).Face()).Shape();
  TopExp_Explorer faces(section, TopAbs_FACE);
  if (!faces.More()) return;
  const TopoDS_Face face = TopoDS::Face(faces.Current());
  const double step = 1.0;  // many rings: the offsets' cost shows
  int occtRings = 0, clipperRings = 0;
  const double occt = bestOf(3, [&] {
    occtRings = 0;
    for (int k = 1; k < 100; ++k) {
      BRepOffsetAPI_MakeOffset offset(face, GeomAbs_Arc);
      offset.Perform(-k * step);
      if (!offset.IsDone() || offset.Shape().IsNull()) break;
      TopExp_Explorer edges(offset.Shape(), TopAbs_EDGE);
      if (!edges.More()) break;
      ++occtRings;
    }
  });
  const double clipper = bestOf(3, [&] {
    ClipperLib::Paths polygon;
    for (TopExp_Explorer wires(face, TopAbs_WIRE); wires.More(); wires.Next()) {
      ClipperLib::Path path;
      for (BRepTools_WireExplorer e(TopoDS::Wire(wires.Current()), face); e.More(); e.Next()) {
        BRepAdaptor_Curve curve(e.Current());
        GCPnts_QuasiUniformDeflection points(curve, 0.01);
        const bool reversed = e.Current().Orientation() == TopAbs_REVERSED;
        for (int i = 1; i < points.NbPoints(); ++i) {
          const gp_Pnt p = points.Value(reversed ? points.NbPoints() - i + 1 : i);
          path.push_back({static_cast<ClipperLib::cInt>(p.X() * 1e4), static_cast<ClipperLib::cInt>(p.Y() * 1e4)});
        }
      }
      polygon.push_back(path);
    }
    clipperRings = 0;
    for (int k = 1; k < 100; ++k) {
      ClipperLib::ClipperOffset offset(2.0, 100.0);
      offset.AddPaths(polygon, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
      ClipperLib::Paths ring;
      offset.Execute(ring, -k * step * 1e4);
      if (ring.empty()) break;
      ++clipperRings;
    }
  });
  std::printf("offsets of a section every %.1f mm: Clipper %.1f ms (%d rings), OCCT MakeOffset %.1f ms (%d rings): "
              "Clipper %.0f x faster\n", step, 1e3 * clipper, clipperRings, 1e3 * occt, occtRings, occt / clipper);
}

// What two threads of plain arithmetic get from the machine now, against one (2.0 on two idle cores): the
// ceiling of any speed-up measured beside it while other work shares the cores.
double machineSpeedUp() {
  const auto spin = [] {
    volatile double x = 1.0;
    for (long i = 0; i < 60'000'000; ++i) x = x * 1.0000001 + 1e-9;
  };
  const double one = bestOf(1, spin);
  const double two = bestOf(1, [&] {
    std::thread other(spin);
    spin();
    other.join();
  });
  return 2.0 * one / two;
}

// Part 3 (material removal of one strategy on the impeller at 0.2 mm < 10 s on two cores;
// < 3 s on two threads and >= 1.8 x over one): each strategy's sweeps of all channels simulated on 1 and 2
// threads (or on `threads` alone when > 0), the best of `runs` each (taken in turn), the speed-up and the CPU
// seconds in the same run, and what the machine gave two threads of plain arithmetic just before.
void removal(const PartAndStock& wheel, const VolumeToRemove& volume, const std::string& only, int threads, int runs) {
  for (Strategy strategy : {Strategy::PlanesParallelToFace, Strategy::CoaxialCylinders, Strategy::SetupPlanes,
                            Strategy::StockOffsets, Strategy::HubOffsets}) {
    if (only != "all" && only != "S" + std::to_string(static_cast<int>(strategy))) continue;
    std::vector<std::vector<ToolMove>> regions;
    for (const RemovalSolid& solid : volume.solids)
      regions.push_back(sweep(partition(solid, wheel.part, strategy), solid, wheel.part, wheel.stock, {}).moves);
    const std::vector<ToolMove> moves = joinSweeps(regions, wheel.stock);
    const std::vector<int> counts = threads > 0 ? std::vector<int>{threads} : std::vector<int>{1, 2};
    std::vector<double> seconds(counts.size(), 1e300), cpu(counts.size());
    RemovalResult r;
    const double machine = threads > 0 ? 0.0 : machineSpeedUp();
    for (int run = 0; run < runs; ++run)
      for (size_t c = 0; c < counts.size(); ++c) {
        RemovalSettings settings;
        settings.threads = counts[c];
        const double before = cpuSeconds();
        CALLGRIND_START_INSTRUMENTATION;
        CACHEGRIND_START_INSTRUMENTATION;
        const double t = bestOf(1, [&] { r = simulateRemoval(moves, SweepSettings().cutter, wheel.stock, wheel.part, settings); });
        CALLGRIND_STOP_INSTRUMENTATION;
        CACHEGRIND_STOP_INSTRUMENTATION;
        if (t < seconds[c]) seconds[c] = t, cpu[c] = cpuSeconds() - before;
      }
    std::string times;
    for (size_t i = 0; i < counts.size(); ++i) {
      char text[120];
      std::snprintf(text, sizeof text, "%s%.2f s on %d thread%s (CPU %.2f s)", i ? ", " : "", seconds[i], counts[i],
                    counts[i] > 1 ? "s" : "", cpu[i]);
      times += text;
    }
    if (counts.size() == 2) {
      char text[160];
      std::snprintf(text, sizeof text, " (x%.2f, target < 3 s on 2 and x1.8; plain arithmetic got x%.2f)", seconds[0] / seconds[1],
                    machine);
      times += text;
    }
    std::printf("removal %-22s at %.2f mm: %s: %ld rays, %ld positions; V_r %.1f %%, feed %.0f mm, in material %.1f %%, "
                "stick-out %.1f mm, gouge %.2f mm3, stock on the part %.2f mean / %.2f max / %.2f std mm\n",
                strategyName(strategy).c_str(), r.resolution, times.c_str(), r.rays, r.positions, r.remainingShare,
                r.feedLength, r.inMaterialShare, r.stickOut, r.gougeVolume, r.thicknessMean, r.thicknessMax,
                r.thicknessStd);
    std::fflush(stdout);
  }
}

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
  if (argc > 2 && std::string(argv[2]) == "removal") {  // part 3 alone
    removal(wheel, volume, argc > 3 ? argv[3] : "all", argc > 4 ? std::atoi(argv[4]) : 0, runs);
    return 0;
  }
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
      PartitionSettings settings;
      settings.step = step;
      const double t = bestOf(1, [&] { p = partition(channel, wheel.part, strategy, settings); });
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
  sweeps(wheel, volume, runs);
  offsets(channel);
  removal(wheel, volume, "all", 0, 1);
  return 0;
}
