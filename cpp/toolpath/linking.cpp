#include "toolpath/linking.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <algorithm>
#include <cmath>

namespace hsm::toolpath::detail {

namespace {
double meanHeight(const std::vector<std::vector<Pass>>& lines) {
  double sum = 0.0;
  long n = 0;
  for (const auto& line : lines)
    for (const Pass& p : line)
      for (const Vector3& x : p) {
        sum += x.z();
        ++n;
      }
  return n ? sum / n : 0.0;
}

// A G1 link from the end of a pass to the start of the next that follows the surface (dropped, so it
// cannot gouge), or none when it would climb a wall (lifted more than the tool radius above the straight
// line): then the tool retracts instead.
std::vector<Vector3> surfaceLink(Context& context, const Vector3& from, const Vector3& to) {
  const FinishingSettings& s = context.settings();
  const int steps = std::max(2, int(std::ceil((to - from).head<2>().norm() / s.sampling)));
  const double span = (to - from).head<2>().norm();
  auto line = [&](const Vector2& p) {
    return span > 0.0 ? from.z() + (to.z() - from.z()) * (p - from.head<2>()).norm() / span : from.z();
  };
  std::vector<Vector3> samples{from};
  for (int i = 1; i < steps; ++i) {
    Vector3 p = from + (to - from) * double(i) / steps;
    const double straight = p.z();
    p.z() = std::max(p.z(), context.tipAt(p.x(), p.y()));
    if (p.z() - straight > s.toolRadius) return {};
    samples.push_back(p);
  }
  samples.push_back(to);
  // Refined between the samples as passes are: a link over an edge bends, and its chords must not cut.
  std::vector<Vector3> link;
  SurfaceBallDrop::Result state;
  bool haveGuess = false;
  for (size_t k = 1; k < samples.size(); ++k) {
    context.bisect(samples[k - 1], samples[k], 0, link, state, haveGuess, line);
    if (k + 1 < samples.size()) link.push_back(samples[k]);
  }
  return link;
}

// A feed move to `p`, unless the tool is there already (a pass that starts where the previous one ended:
// a zero-length G1 is noise that posts round away).
void addFeed(Toolpath& path, const Vector3& p) {
  if (!path.moves.empty() && (path.moves.back().point - p).norm() < 1e-4) return;
  path.moves.push_back({p, false});
}

// Links passes into moves: zigzag neighbours by a surface-following G1 when close, else retract.
Toolpath assemble(Context& context, std::vector<std::vector<Pass>> lines) {
  const FinishingSettings& s = context.settings();
  Toolpath path;
  path.safeHeight = context.safeHeight();
  // Zigzag: every other line (a plane, or a morphed pass) runs backwards, its pieces in reverse order too.
  std::vector<Pass> passes;
  for (size_t k = 0; k < lines.size(); ++k) {
    if (s.zigzag && k % 2 == 1) {
      std::reverse(lines[k].begin(), lines[k].end());
      for (Pass& piece : lines[k]) std::reverse(piece.begin(), piece.end());
    }
    passes.insert(passes.end(), lines[k].begin(), lines[k].end());
  }
  const double linkLimit = 10.0 * s.toolRadius;
  bool inside = false;  // the tool is down at the end of the previous pass
  for (const Pass& pass : passes) {
    if (pass.size() < 2) continue;
    ++path.passes;
    double length = 0.0;
    for (size_t k = 1; k < pass.size(); ++k) length += (pass[k] - pass[k - 1]).norm();
    path.passLengths.push_back(length);
    const Vector3& start = pass.front();
    std::vector<Vector3> link;
    if (inside && s.zigzag && (start - path.moves.back().point).norm() <= linkLimit)
      link = surfaceLink(context, path.moves.back().point, start);
    if (!link.empty()) {
      for (const Vector3& p : link) addFeed(path, p);
    } else {
      if (inside) path.moves.push_back({Vector3(path.moves.back().point.x(), path.moves.back().point.y(), path.safeHeight), true});
      path.moves.push_back({Vector3(start.x(), start.y(), path.safeHeight), true});
      path.moves.push_back({Vector3(start.x(), start.y(), start.z() + 1.0), true});
    }
    for (const Vector3& p : pass) addFeed(path, p);
    inside = true;
  }
  if (inside) path.moves.push_back({Vector3(path.moves.back().point.x(), path.moves.back().point.y(), path.safeHeight), true});
  return path;
}

// Groups (areas) of lines (passes, each in pieces) in sweeping order: upward starts on the lower side.
void orderForSweep(std::vector<std::vector<std::vector<Pass>>>& groups, Sweep sweep) {
  groups.erase(std::remove_if(groups.begin(), groups.end(), [](const auto& g) { return g.empty(); }), groups.end());
  if (groups.empty()) return;
  // Several areas: compare the first and last areas; one area: its first and last passes.
  const bool single = groups.size() == 1;
  const double firstHeight = single ? meanHeight({groups.front().front()}) : meanHeight(groups.front());
  const double lastHeight = single ? meanHeight({groups.front().back()}) : meanHeight(groups.back());
  const bool climbing = lastHeight >= firstHeight;
  if (climbing != (sweep == Sweep::Upward)) {
    std::reverse(groups.begin(), groups.end());
    for (auto& g : groups) std::reverse(g.begin(), g.end());
  }

}

// The lines (each a list of pass pieces) of all groups, in order.
std::vector<std::vector<Pass>> lines(const std::vector<std::vector<std::vector<Pass>>>& groups) {
  std::vector<std::vector<Pass>> all;
  for (const auto& g : groups) all.insert(all.end(), g.begin(), g.end());
  return all;
}
}  // namespace

// The passes of all groups linked into moves; refuses a result with no pass at all (nothing to cut).
Toolpath finish(Context& context, std::vector<std::vector<std::vector<Pass>>> groups, int bottomFace,
                const std::string& why) {
  orderForSweep(groups, context.settings().sweep);
  if (groups.empty())
    throw InputError("no pass of the " + mm(2.0 * context.settings().toolRadius) + " ball rests on " +
                     faceName(bottomFace) + ": " + why);
  Toolpath path = assemble(context, lines(groups));
  path.droppedPoints = context.dropped;
  path.warnings.insert(path.warnings.begin(), context.warnings.begin(), context.warnings.end());
  context.report(1.0);
  return path;
}

}  // namespace hsm::toolpath::detail
