#include "toolpath/passes.hpp"

#include "common/parallel.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <algorithm>
#include <cmath>

namespace hsm::toolpath::detail {

namespace {
constexpr double kStationStep = 1.0;  // mm between the points that decide the stepover
}  // namespace

// The parameters of the passes from `begin` to `end`: each the farthest that keeps the cusp height.
// Progress: the first half of `phase`.
std::vector<double> passParameters(Context& context, const Family& family, bool skipFirst, Phase phase) {
  std::vector<double> parameters;
  double current = family.begin;
  if (!skipFirst) parameters.push_back(current);
  const double span = std::abs(family.end - family.begin), sense = family.end > family.begin ? 1.0 : -1.0;
  double lastStep = 1e-3 * span;
  while (std::abs(current - family.begin) < span - 1e-12) {
    const std::vector<Vector2> plan = family.plan(current, kStationStep);
    const std::vector<BallContact> here = context.gauge().contacts(plan);
    const double h = context.settings().cuspHeight, flat = context.flatStep();
    auto fits = [&](double candidate) {
      const std::vector<Vector2> candidatePlan = family.plan(candidate, kStationStep);
      const std::vector<BallContact> there = context.gauge().contacts(candidatePlan);
      for (size_t k = 0; k < here.size() && k < there.size(); ++k) {
        if (!there[k].inside) continue;
        // Where the current pass is off the face (or its cusp cannot be told), the next may not step by
        // more than the flat-face stepover in plan: the passes must not jump over a corner.
        const std::optional<double> cusp = context.gauge().cusp(here, k, candidatePlan, there, h);
        if (cusp ? *cusp > h : (candidatePlan[k] - plan[k]).norm() > flat) return false;
      }
      return true;
    };
    // Bracket the next pass from the last step (doubling while it fits), then bisect to 1 % of the step.
    double lo = current, step = std::max(lastStep, 1e-6 * span), hi = current;
    for (;;) {
      hi = sense > 0 ? std::min(current + sense * step, family.end) : std::max(current + sense * step, family.end);
      if (!fits(hi)) break;
      lo = hi;
      if (hi == family.end) break;
      step *= 2.0;
    }
    if (lo != family.end) {
      const double resolution = 0.01 * std::abs(hi - current);
      while (std::abs(hi - lo) > resolution) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
      }
    }
    lastStep = std::max(std::abs(lo - current), 1e-6 * span);
    if (std::abs(lo - current) < 1e-9 * span) lo = current + sense * 1e-3 * span;  // always move on
    current = sense > 0 ? std::min(lo, family.end) : std::max(lo, family.end);
    parameters.push_back(current);
    context.report(phase.at(0.5 * std::abs(current - family.begin) / span));
  }
  return parameters;
}

// The passes of a family cut along the parameters; progress: the second half of `phase`.
std::vector<std::vector<Pass>> cutPasses(Context& context, const Family& family, const std::vector<double>& parameters,
                                         Phase phase) {
  // The plans first, in order (a family may fill a cache as it goes), then the passes cut side by side on the
  // threads asked for, one pass a chunk (a pass costs what its length and the surface under it ask); each
  // pass's drop is then single-threaded. Progress is reported from this thread.
  const long n = static_cast<long>(parameters.size());
  std::vector<std::vector<Vector2>> plans;
  plans.reserve(parameters.size());
  for (double parameter : parameters) plans.push_back(family.plan(parameter, context.settings().sampling));
  std::vector<std::vector<Pass>> cuts(parameters.size());
  parallelChunksReporting(
      n, context.settings().threads, 1,
      [&](long from, long to) {
        for (long k = from; k < to; ++k) cuts[static_cast<size_t>(k)] = context.cut(plans[static_cast<size_t>(k)], 1);
      },
      [&](long done) { context.report(phase.at(0.5 + 0.5 * double(done) / double(std::max(1L, n)))); });
  std::vector<std::vector<Pass>> lines;
  for (std::vector<Pass>& cut : cuts)
    if (!cut.empty()) lines.push_back(std::move(cut));
  return lines;
}

}  // namespace hsm::toolpath::detail
