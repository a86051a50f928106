// Curve nets on the master bottom feature. Target: 13 curves at P = 5 mm in under 50 ms, so that the
// K/P preview stays interactive. Run: build/bin/bench_curvenet
#include "curvenet/curvenet.hpp"
#include "curvenet/regions.hpp"
#include "support/master_feature.hpp"

#include <benchmark/benchmark.h>

using namespace hsm;
using namespace hsm::curvenet;

namespace {
constexpr auto feature = test::masterFeature;  // loaded once per program

NetSettings settings(bool onFace) {
  NetSettings s;
  s.step = 5.0;
  if (onFace) s.face = feature().bottom;
  return s;
}

void netOf13Curves(benchmark::State& state) {
  const bool onFace = state.range(0) != 0;
  size_t curves = 0;
  for (auto _ : state) {
    const CurveNet net = curveNet({feature().boundary1, feature().boundary2}, 0.25, NetMode::BoundariesToMedian,
                                  settings(onFace));
    curves = net.curves.size() - 2;
    benchmark::DoNotOptimize(net.curves.data());
  }
  state.counters["curves"] = static_cast<double>(curves);
  state.SetLabel(onFace ? "on the bottom face" : "without face");
}
BENCHMARK(netOf13Curves)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void fourStepMethod(benchmark::State& state) {
  GuidanceSettings s;
  s.net = settings(true);
  for (auto _ : state) benchmark::DoNotOptimize(guidanceCurves({feature().boundary1, feature().boundary2}, s));
}
BENCHMARK(fourStepMethod)->Unit(benchmark::kMillisecond);

void regionsOfFourAreas(benchmark::State& state) {
  GuidanceSettings s;
  s.net = settings(true);
  const GuidanceResult result = guidanceCurves({feature().boundary1, feature().boundary2}, s);
  for (auto _ : state) benchmark::DoNotOptimize(areaRegions(result.net, feature().bottom));
}
BENCHMARK(regionsOfFourAreas)->Unit(benchmark::kMillisecond);
}  // namespace
