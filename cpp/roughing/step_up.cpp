// Intermediate levels of a slice and the passes that cut what the levels below left (step_up.hpp).
#include "roughing/step_up.hpp"

#include "roughing/flat.hpp"

#include <algorithm>
#include <cmath>

namespace hsm::roughing {

namespace {

// Cleared is taken this far out (mm): a loop running along the cleared domain's own boundary cuts nothing.
double clearedMargin(double tolerance) { return std::max(0.05, 2.0 * tolerance); }

struct Span {
  double from, to;  // mm along the loop; may run past its start or its end (the loop is closed)
};

// The point `t` mm along the closed loop p (arc lengths s, s.back() the whole loop).
cl::IntPoint pointAlong(const cl::Path& p, const std::vector<double>& s, double t) {
  const double total = s.back();
  t = std::fmod(t, total);
  if (t < 0.0) t += total;
  const size_t i = std::min<size_t>(p.size() - 1, std::upper_bound(s.begin(), s.end(), t) - s.begin() - 1);
  const cl::IntPoint& a = p[i];
  const cl::IntPoint& b = p[(i + 1) % p.size()];
  const double f = s[i + 1] > s[i] ? (t - s[i]) / (s[i + 1] - s[i]) : 0.0;
  return {static_cast<cl::cInt>(std::llround(double(a.X) + f * double(b.X - a.X))),
          static_cast<cl::cInt>(std::llround(double(a.Y) + f * double(b.Y - a.Y)))};
}

// The loop's own points (`own`: not one it was only read at) from `span.from` to `span.to` mm along it, and
// its ends. (A loop's points are where its moves must turn, or where a surface laid flat needs them.)
cl::Path piece(const cl::Path& p, const std::vector<char>& own, const std::vector<double>& s, const Span& span) {
  cl::Path out{pointAlong(p, s, span.from)};
  const double total = s.back();
  for (int wrap = -1; wrap <= 1; ++wrap)
    for (size_t i = 0; i < p.size(); ++i) {
      const double t = s[i] + wrap * total;
      if (own[i] && t > span.from && t < span.to) out.push_back(p[i]);
    }
  out.push_back(pointAlong(p, s, span.to));
  return out;
}

// The open pieces of loop p (a point of which is not fresh) where its points are fresh, lengthened by
// `lead` at both ends and joined where they meet; or the whole loop, closed, when they cover it.
void piecesOf(cl::Path p, std::vector<char> own, std::vector<char> fresh, double lead, int ring,
              std::vector<FlatPass>& out) {
  const size_t n = p.size();
  const size_t first = static_cast<size_t>(std::find(fresh.begin(), fresh.end(), 0) - fresh.begin());
  std::rotate(p.begin(), p.begin() + first, p.end());  // start on a point that is not fresh
  std::rotate(own.begin(), own.begin() + first, own.end());
  std::rotate(fresh.begin(), fresh.begin() + first, fresh.end());
  std::vector<double> s(n + 1, 0.0);
  for (size_t i = 1; i <= n; ++i) s[i] = s[i - 1] + pathLength({p[i - 1], p[i % n]});
  const double total = s[n];
  std::vector<Span> spans;
  for (size_t i = 1; i < n; ++i) {
    if (!fresh[i] || fresh[i - 1]) continue;
    size_t j = i;
    while (j + 1 < n && fresh[j + 1]) ++j;
    const Span span{s[i - 1] - lead, s[j + 1] + lead};  // from the last point before to the first after
    if (!spans.empty() && span.from <= spans.back().to) spans.back().to = span.to;
    else spans.push_back(span);
    i = j;
  }
  if (spans.size() > 1 && spans.back().to - total >= spans.front().from) {  // the last runs into the first
    spans.front().from = spans.back().from - total;
    spans.pop_back();
  }
  for (const Span& span : spans) {
    if (span.to - span.from >= total) {
      out.push_back({p, true, ring});
      return;
    }
  }
  for (const Span& span : spans) out.push_back({piece(p, own, s, span), false, ring});
}

}  // namespace

std::vector<double> stepUpHeights(double low, double high, const DomainAt& domainAt, double minimum, double scallop,
                                  double tolerance) {
  std::vector<double> heights;
  if (!(minimum > 0.0)) return heights;
  const double margin = clearedMargin(tolerance);
  auto split = [&](auto&& self, double lo, double hi) -> void {
    const double s = hi - lo;
    if (s < 2.0 * minimum - 1e-9 || s <= scallop) return;
    const double width = scallop * s / std::sqrt(s * s - scallop * scallop);
    const cl::Paths band = boolean(cl::ctDifference, domainAt(hi), offset(domainAt(lo), margin, tolerance));
    if (offset(band, -0.5 * width, tolerance).empty()) return;
    const double middle = 0.5 * (lo + hi);
    self(self, middle, hi);
    heights.push_back(middle);
    self(self, lo, middle);
  };
  split(split, low, high);
  return heights;
}

std::vector<FlatPass> passesBeyond(const Rings& rings, const cl::Paths& cleared, double width, double lead,
                                   double spacing, double tolerance, const cl::Paths* within) {
  std::vector<FlatPass> out;
  const double beyond = std::max(width, clearedMargin(tolerance));
  const cl::Paths done = cleared.empty() ? cl::Paths{} : offset(cleared, beyond, tolerance);
  for (size_t k = 0; k < rings.loops.size(); ++k)
    for (const cl::Path& loop : rings.loops[k]) {
      if (loop.size() < 3) continue;
      const size_t first = out.size();
      if (done.empty() && !within) {
        out.push_back({loop, true, static_cast<int>(k)});
      } else {
        // The loop read at points `spacing` apart, its own points marked.
        cl::Path dense;
        std::vector<char> own;
        for (size_t i = 0; i < loop.size(); ++i) {
          cl::Paths edge{{loop[i], loop[(i + 1) % loop.size()]}};
          densify(edge, spacing, false);
          for (size_t j = 0; j + 1 < edge[0].size(); ++j) dense.push_back(edge[0][j]), own.push_back(j == 0);
        }
        std::vector<char> fresh(dense.size());
        size_t count = 0;
        for (size_t i = 0; i < dense.size(); ++i)
          count += (fresh[i] = !insidePaths(dense[i], done) && (!within || insidePaths(dense[i], *within)));
        if (count == fresh.size()) out.push_back({loop, true, static_cast<int>(k)});
        else if (count > 0) piecesOf(dense, own, fresh, lead, static_cast<int>(k), out);
      }
      for (size_t i = first; i < out.size(); ++i) out[i].depth = rings.depths[k];
    }
  return out;
}

}  // namespace hsm::roughing
