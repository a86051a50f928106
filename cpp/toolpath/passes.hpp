// Pass stepping (internal): a one-parameter family of plan polylines cut into passes spaced for the cusp
// height.
#pragma once

#include "toolpath/finishing_context.hpp"

#include <functional>
#include <vector>

namespace hsm::toolpath::detail {

// A one-parameter family of passes: parameter → plan polyline (coarse for the stepover, fine for cutting).
struct Family {
  std::function<std::vector<Vector2>(double parameter, double spacing)> plan;
  double begin = 0.0, end = 1.0;
};

// The share of the work a phase stands for: progress from `base` over `width`.
struct Phase {
  double base = 0.0, width = 1.0;
  double at(double done) const { return base + width * done; }
};

// The parameters of the passes from `begin` to `end`: each the farthest that keeps the cusp height.
// Progress: the first half of `phase`.
std::vector<double> passParameters(Context& context, const Family& family, bool skipFirst, Phase phase);

// The passes of a family cut along the parameters; progress: the second half of `phase`.
std::vector<std::vector<Pass>> cutPasses(Context& context, const Family& family, const std::vector<double>& parameters,
                                         Phase phase);

}  // namespace hsm::toolpath::detail
