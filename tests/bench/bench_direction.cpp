// The optimal machining direction. Target: a 100 × 100 mm face sampled on a 50 × 50 grid, directions
// at 1°, in under 1 s. The face: the case-2-like valleys (15 mm deep, 45 mm apart, running at 45°), a
// bicubic B-spline as a CAD system gives it. Run: build/bin/bench_direction
#include "direction/direction.hpp"
#include "support/surfaces.hpp"

#include <benchmark/benchmark.h>

using namespace hsm;
using namespace hsm::direction;

namespace {
CuttingConditions case2() {
  CuttingConditions c;  // Ø10 ball, Sz 0.01 mm, fz 0.2 mm at 15,000 rpm and Z 2: 6000 mm/min
  c.toolRadius = 5.0;
  c.spindleSpeed = 250.0;
  c.programmedFeed = 100.0;
  return c;
}

kinematics::MachineModel mikron() {
  kinematics::MachineModel machine;  // the defaults are the Mikron UCP 710's axes: X 2.5 m/s², 5 m/s³
  return machine;
}

void optimalDirectionOfAFace(benchmark::State& state) {
  const TopoDS_Face face = test::slantedValleys(100.0, 15.0, 45.0, 41);
  const int grid = static_cast<int>(state.range(0));
  DirectionResult result;
  for (auto _ : state) {
    result = optimalDirection(face, case2(), mikron(), DirectionSettings{grid, grid, 1.0, 0.95});
    benchmark::DoNotOptimize(result.rate.data());
  }
  state.counters["points"] = static_cast<double>(result.points.rows());
  state.counters["beams_deg"] = result.optimalAngleDeg;
  state.counters["least_time_deg"] = result.fastestAngleDeg;
}
BENCHMARK(optimalDirectionOfAFace)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);
}  // namespace
