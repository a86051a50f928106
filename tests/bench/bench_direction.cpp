// The optimal machining direction. Issue figure: a 100 × 100 mm face sampled on a 50 × 50 grid, directions
// at 1°, in under 1 s. The face: the case-2-like valleys (15 mm deep, 45 mm apart, running at 45°), a
// bicubic B-spline as a CAD system gives it. Run: build/bin/bench_direction
#include "direction/direction.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <benchmark/benchmark.h>

#include <cmath>

using namespace hsm::direction;

namespace {
TopoDS_Face valleys() {
  const int n = 41;
  TColgp_Array2OfPnt grid(1, n, 1, n);
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= n; ++j) {
      const double x = 100.0 * (i - 1) / (n - 1), y = 100.0 * (j - 1) / (n - 1), u = (y - x) / std::sqrt(2.0);
      grid.SetValue(i, j, gp_Pnt(x, y, 7.5 * (1.0 - std::cos(2.0 * M_PI * u / 45.0))));
    }
  const Handle(Geom_BSplineSurface) surface = GeomAPI_PointsToBSplineSurface(grid, 3, 8, GeomAbs_C2, 1e-6).Surface();
  return BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
}

CuttingConditions case2() {
  CuttingConditions c;  // Ø10 ball, Sz 0.01 mm, fz 0.2 mm at 15,000 rpm and Z 2: 6000 mm/min; a 2.5 m/s²
  c.toolRadius = 5.0;
  c.spindleSpeed = 250.0;
  c.programmedFeed = 100.0;
  c.acceleration = 2500.0;
  c.stopJerk = 5000.0;
  return c;
}

void optimalDirectionOfAFace(benchmark::State& state) {
  const TopoDS_Face face = valleys();
  const int grid = static_cast<int>(state.range(0));
  DirectionResult result;
  for (auto _ : state) {
    result = optimalDirection(face, case2(), DirectionSettings{grid, grid, 1.0, 0.95});
    benchmark::DoNotOptimize(result.rate.data());
  }
  state.counters["points"] = static_cast<double>(result.points.rows());
  state.counters["beams_deg"] = result.optimalAngleDeg;
  state.counters["least_time_deg"] = result.fastestAngleDeg;
}
BENCHMARK(optimalDirectionOfAFace)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);
}  // namespace
