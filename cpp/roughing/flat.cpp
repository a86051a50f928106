// 2-D offsets, booleans and shadows of a level laid flat (flat.hpp), in Clipper's integers of 0.1 µm.
#include "roughing/flat.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace hsm::roughing {

cl::Paths offset(const cl::Paths& paths, double mm, double tolerance) {
  cl::ClipperOffset offsetter(2.0, std::max(1.0, tolerance * kScale));
  offsetter.AddPaths(paths, cl::jtRound, cl::etClosedPolygon);
  cl::Paths result;
  offsetter.Execute(result, mm * kScale);
  return result;
}

cl::Paths boolean(cl::ClipType type, const cl::Paths& a, const cl::Paths& b) {
  cl::Clipper clipper;
  clipper.AddPaths(a, cl::ptSubject, true);
  clipper.AddPaths(b, cl::ptClip, true);
  cl::Paths result;
  clipper.Execute(type, result, cl::pftNonZero, cl::pftNonZero);
  return result;
}

cl::Paths united(const cl::Paths& pieces) {
  cl::Clipper clipper;
  clipper.AddPaths(pieces, cl::ptSubject, true);
  cl::Paths result;
  clipper.Execute(cl::ctUnion, result, cl::pftNonZero, cl::pftNonZero);
  return result;
}

double area(const cl::Paths& paths) {
  double sum = 0.0;
  for (const cl::Path& p : paths) sum += cl::Area(p);
  return sum / (kScale * kScale);
}

double pathLength(const cl::Path& path) {
  double length = 0.0;
  for (size_t i = 1; i < path.size(); ++i)
    length += std::hypot(double(path[i].X - path[i - 1].X), double(path[i].Y - path[i - 1].Y));
  return length / kScale;
}

bool insidePaths(const cl::IntPoint& q, const cl::Paths& paths) {
  int winding = 0;
  for (const cl::Path& path : paths) {
    const int in = cl::PointInPolygon(q, path);
    if (in != 0) winding += cl::Orientation(path) ? 1 : -1;
  }
  return winding > 0;
}

namespace {
// Clipper units from p to the segment a–b.
double segmentDistance(const cl::IntPoint& p, const cl::IntPoint& a, const cl::IntPoint& b) {
  const double dx = double(b.X - a.X), dy = double(b.Y - a.Y), px = double(p.X - a.X), py = double(p.Y - a.Y);
  const double squared = dx * dx + dy * dy;
  const double t = squared > 0.0 ? std::clamp((px * dx + py * dy) / squared, 0.0, 1.0) : 0.0;
  return std::hypot(px - t * dx, py - t * dy);
}

}  // namespace

double distanceToBoundary(const cl::IntPoint& q, const cl::Paths& paths) {
  double best = std::numeric_limits<double>::infinity();
  for (const cl::Path& path : paths)
    for (size_t i = 0; i < path.size(); ++i) best = std::min(best, segmentDistance(q, path[i], path[(i + 1) % path.size()]));
  return best / kScale;
}

bool segmentInside(const cl::IntPoint& a, const cl::IntPoint& b, const cl::Paths& paths, double tolerance) {
  cl::Clipper clipper;
  clipper.AddPath(cl::Path{a, b}, cl::ptSubject, false);
  clipper.AddPaths(paths, cl::ptClip, true);
  cl::PolyTree tree;
  clipper.Execute(cl::ctIntersection, tree, cl::pftNonZero, cl::pftNonZero);
  cl::Paths open;
  cl::OpenPathsFromPolyTree(tree, open);
  double inside = 0.0;
  for (const cl::Path& p : open) inside += pathLength(p);
  return inside >= pathLength(cl::Path{a, b}) - tolerance;
}

void densify(cl::Paths& paths, double longest, bool closed) {
  if (!std::isfinite(longest)) return;
  for (cl::Path& path : paths) {
    cl::Path dense;
    const size_t edges = closed ? path.size() : path.size() - std::min<size_t>(path.size(), 1);
    for (size_t i = 0; i < edges; ++i) {
      const cl::IntPoint& a = path[i];
      const cl::IntPoint& b = path[(i + 1) % path.size()];
      dense.push_back(a);
      const double length = std::hypot(double(b.X - a.X), double(b.Y - a.Y)) / kScale;
      const int pieces = static_cast<int>(std::ceil(length / longest));
      for (int k = 1; k < pieces; ++k)
        dense.push_back({static_cast<cl::cInt>(a.X + (b.X - a.X) * double(k) / pieces),
                         static_cast<cl::cInt>(a.Y + (b.Y - a.Y) * double(k) / pieces)});
    }
    if (!closed && !path.empty()) dense.push_back(path.back());
    path = std::move(dense);
  }
}

namespace {
// Douglas–Peucker on one closed path: from its first point and the point farthest from it, each stretch split
// at its farthest point while that is more than `limit` (Clipper units) off its chord.
cl::Path simplified(const cl::Path& path, double limit) {
  const size_t n = path.size();
  size_t far = 0;
  double farthest = 0.0;
  for (size_t i = 1; i < n; ++i) {
    const double d = std::hypot(double(path[i].X - path[0].X), double(path[i].Y - path[0].Y));
    if (d > farthest) farthest = d, far = i;
  }
  if (far == 0) return {};
  std::vector<char> keep(n, 0);
  keep[0] = keep[far] = 1;
  std::vector<std::pair<size_t, size_t>> stretches{{0, far}, {far, n}};  // indices modulo n
  while (!stretches.empty()) {
    const auto [from, to] = stretches.back();
    stretches.pop_back();
    size_t worst = from;
    double most = limit;
    for (size_t k = from + 1; k < to; ++k) {
      const double d = segmentDistance(path[k % n], path[from % n], path[to % n]);
      if (d > most) most = d, worst = k;
    }
    if (worst == from) continue;
    keep[worst % n] = 1;
    stretches.push_back({from, worst});
    stretches.push_back({worst, to});
  }
  cl::Path kept;
  for (size_t i = 0; i < n; ++i)
    if (keep[i]) kept.push_back(path[i]);
  return kept;
}
}  // namespace

void simplify(cl::Paths& paths, double tolerance) {
  cl::Paths kept;
  for (const cl::Path& path : paths) {
    if (path.size() < 3) continue;
    cl::Path simple = simplified(path, tolerance * kScale);
    if (simple.size() >= 3) kept.push_back(std::move(simple));
  }
  paths = std::move(kept);
}

bool Window::misses(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) const {
  return std::max({a.X, b.X, c.X}) < x0 || std::min({a.X, b.X, c.X}) > x1 || std::max({a.Y, b.Y, c.Y}) < y0 ||
         std::min({a.Y, b.Y, c.Y}) > y1;
}

Window windowAround(const cl::Paths& paths, double margin) {
  Window w;
  if (paths.empty()) return w;
  const cl::IntRect r = [&] {
    cl::Clipper c;
    c.AddPaths(paths, cl::ptSubject, true);
    return c.GetBounds();
  }();
  w.x0 = double(r.left) - margin * kScale, w.x1 = double(r.right) + margin * kScale;
  w.y0 = double(r.top) - margin * kScale, w.y1 = double(r.bottom) + margin * kScale;
  return w;
}

namespace {

// The straight edge a–b laid flat, from a (included) towards b (excluded): points added at midpoints while the
// projection bows it.
void addFlatEdge(const Projection& projection, const Eigen::Vector3d& a, const Eigen::Vector3d& b, int depth,
                 cl::Path& path) {
  if (depth < 6 && projection.bends(a, b)) {
    const Eigen::Vector3d m = 0.5 * (a + b);
    addFlatEdge(projection, a, m, depth + 1, path);
    addFlatEdge(projection, m, b, depth + 1, path);
    return;
  }
  path.push_back(projection.plane(a));
}

// The polygon `p` (heights h) cut to the side of height `at` that `above` says, heights interpolated along
// the edges.
void cutAt(std::vector<Eigen::Vector3d>& p, std::vector<double>& h, double at, bool above) {
  std::vector<Eigen::Vector3d> kept;
  std::vector<double> heights;
  const auto in = [&](double x) { return above ? x >= at : x < at; };
  for (size_t i = 0; i < p.size(); ++i) {
    const size_t j = (i + 1) % p.size();
    if (in(h[i])) kept.push_back(p[i]), heights.push_back(h[i]);
    if (in(h[i]) != in(h[j])) {
      kept.push_back(p[i] + (p[j] - p[i]) * ((at - h[i]) / (h[j] - h[i])));
      heights.push_back(at);
    }
  }
  p = std::move(kept), h = std::move(heights);
}

// The triangle's part within heights [from, to[ laid flat, added to `pieces`: the polygon of its edges'
// images (bowed where the projection bends straight edges), counter-clockwise so that a union is non-zero.
void addProjected(const Projection& projection, const Eigen::Vector3d (&t)[3], const double (&h)[3], double from,
                  double to, cl::Paths& pieces) {
  std::vector<Eigen::Vector3d> p(t, t + 3);
  std::vector<double> heights(h, h + 3);
  if (std::min({h[0], h[1], h[2]}) < from) cutAt(p, heights, from, true);
  if (std::isfinite(to) && std::max({h[0], h[1], h[2]}) >= to) cutAt(p, heights, to, false);
  if (p.size() < 3) return;
  cl::Path path;
  for (size_t i = 0; i < p.size(); ++i) addFlatEdge(projection, p[i], p[(i + 1) % p.size()], 0, path);
  if (path.size() < 3) return;
  if (!cl::Orientation(path)) cl::ReversePath(path);
  if (cl::Area(path) > 0.0) pieces.push_back(std::move(path));
}

// Whether the plane's scales differ by more than 5 % over the triangle's corners: its shadow, grown at its
// least scales, would then be grown too much at its other end (at 15 %, 0.2–0.6 mm too much on an impeller's
// unrolled levels; at 10 %, the hub offsets' outer passes kept 0.1–0.3 mm more than at 5 %).
bool scalesVary(const Eigen::Vector2d (&s)[3]) {
  const Eigen::Vector2d low = s[0].cwiseMin(s[1]).cwiseMin(s[2]), high = s[0].cwiseMax(s[1]).cwiseMax(s[2]);
  return high.x() > 1.05 * low.x() || high.y() > 1.05 * low.y();
}

// The triangles of one band laid flat that are grown alike, and the least scales and convexity among them.
struct Bin {
  cl::Paths pieces;
  Eigen::Vector2d scales{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double convexity = std::numeric_limits<double>::infinity();
};
using Bins = std::map<long long, Bin>;
constexpr long long kMaxBands = 64;  // a bin's key is its class's times this, plus its band
constexpr long long kScaleLevels = 512;  // a keep-out class's scale steps (1e-3 to 1e3 in steps of 5 %: ±142)

// A triangle's class: the key of the bins it goes in (one per band), its least scales and convexity.
struct Class {
  long long key = 0;
  Eigen::Vector2d scales{1.0, 1.0};
  double convexity = 0.0;
};

template <class ClassOf>
void addTriangle(const Projection& projection, const Eigen::Vector3d (&p)[3], const std::vector<Band>& bands,
                 int depth, ClassOf& classOf, Bins& bins) {
  const Eigen::Vector2d s[3] = {projection.scalesAt(p[0]), projection.scalesAt(p[1]), projection.scalesAt(p[2])};
  if (depth < 3 && scalesVary(s)) {  // in four, by its edges' middles
    const Eigen::Vector3d m[3] = {0.5 * (p[0] + p[1]), 0.5 * (p[1] + p[2]), 0.5 * (p[2] + p[0])};
    const Eigen::Vector3d quarters[4][3] = {{p[0], m[0], m[2]}, {m[0], p[1], m[1]}, {m[2], m[1], p[2]}, {m[0], m[1], m[2]}};
    for (const auto& q : quarters) addTriangle(projection, q, bands, depth + 1, classOf, bins);
    return;
  }
  const double h[3] = {projection.height(p[0]), projection.height(p[1]), projection.height(p[2])};
  const double low = std::min({h[0], h[1], h[2]}), high = std::max({h[0], h[1], h[2]});
  const Class c = classOf(p, s[0].cwiseMin(s[1]).cwiseMin(s[2]));
  for (size_t b = 0; b < bands.size(); ++b)
    if (high >= bands[b].from && low < bands[b].to) {
      Bin& bin = bins[c.key * kMaxBands + static_cast<long long>(b)];
      bin.scales = bin.scales.cwiseMin(c.scales);
      bin.convexity = std::min(bin.convexity, c.convexity);
      addProjected(projection, p, h, bands[b].from, bands[b].to, bin.pieces);
    }
}

// The mesh's triangles laid flat, each cut to each band of `bands` (heights [from, to[) it meets, leaving out
// those outside `window`, split where the plane's scales vary over them, gathered in bins by their class
// (`classOf(triangle, its least scales)`) and band: what stands over the surface, seen along the tool axis. The mesh is of
// closed solids, its triangles facing out: on planes only those facing the spindle are needed (a ray along the
// tool axis from any point of the solid leaves it through one of them), half the union's work. (Unrolled
// cylinders keep every triangle: culled there, S2's levels lost part of their region, 121 against 150 mm of
// cutting on an impeller channel, for a reason not found yet.)
template <class ClassOf>
Bins projectedPieces(const geometry::TriangleMesh& mesh, const Projection& projection, const std::vector<Band>& bands,
                     const Window& window, ClassOf&& classOf) {
  Bins bins;
  const double lowest = bands.front().from;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    const double h[3] = {projection.height(p[0]), projection.height(p[1]), projection.height(p[2])};
    if (!(std::max({h[0], h[1], h[2]}) >= lowest)) continue;
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (projection.cullsBackFaces() && normal.dot(projection.axisAt((p[0] + p[1] + p[2]) / 3.0)) <= 0.0) continue;
    if (projection.skip(p) || window.misses(projection.plane(p[0]), projection.plane(p[1]), projection.plane(p[2])))
      continue;
    addTriangle(projection, p, bands, 0, classOf, bins);
  }
  return bins;
}

// Clipper paths with x scaled by `factor`.
cl::Paths scaledX(cl::Paths paths, double factor) {
  for (cl::Path& path : paths)
    for (cl::IntPoint& q : path) q.X = static_cast<cl::cInt>(std::llround(double(q.X) * factor));
  return paths;
}

}  // namespace

cl::Paths projectedUnion(const geometry::TriangleMesh& mesh, const Projection& projection, double fromHeight,
                         const Window& window) {
  const std::vector<Band> all = {{fromHeight, std::numeric_limits<double>::infinity(), 0.0}};
  return united(projectedPieces(mesh, projection, all, window, [](const Eigen::Vector3d(&)[3], const Eigen::Vector2d&) { return Class{}; })[0].pieces);
}

namespace {

// A triangle's class for its keep-out: its least scales in steps 5 % apart (rounded down) and the least
// convexity under it. The bin is grown at its members' least scales and convexity, on the safe side; the
// convexity (n_r/ρ) varies with the radius as the x scale does, so it is not a class of its own (that split
// the bins into as many again, their outlines with them, for three times the sweep's time).
Class keepOutClass(const Projection& projection, const Eigen::Vector3d (&p)[3], const Eigen::Vector2d& leastScales) {
  constexpr double kRatio = 1.05;
  auto level = [&](double scale) {
    return static_cast<long long>(std::floor(std::log(std::clamp(scale, 1e-3, 1e3)) / std::log(kRatio))) + kScaleLevels / 2;
  };
  Class c;
  c.scales = leastScales;
  c.convexity = std::min({projection.convexityAt(p[0]), projection.convexityAt(p[1]), projection.convexityAt(p[2])});
  c.key = level(c.scales.x()) * kScaleLevels + level(c.scales.y());
  return c;
}

// The ellipse whose common part with the band's disk keeps the centre from triangles whose surface falls away
// across x by `convexityStep` steps (rounded down): none where the disk alone does nearly as well (it grows
// the bin twice).
constexpr double kLeastGain = 0.05;  // mm across
std::optional<Ellipse> narrowerIn(const Band& band, long long convexityStep) {
  if (convexityStep <= 0 || band.convex.empty()) return std::nullopt;
  const Ellipse& e = band.convex[std::min<size_t>(static_cast<size_t>(convexityStep), band.convex.size()) - 1];
  if (!(e.across < band.clearance - kLeastGain)) return std::nullopt;
  return e;
}

// `pieces` grown in true mm by the ellipse `e` over the plane's least scales `s` under them: x stretched by
// sx·along/(sy·across) makes the ellipse a disk of along/sy.
cl::Paths grownBy(const cl::Paths& pieces, const Eigen::Vector2d& s, const Ellipse& e, double tolerance) {
  const double stretch = s.x() * e.along / (s.y() * e.across);
  return scaledX(offset(scaledX(pieces, stretch), e.along / s.y(), tolerance), 1.0 / stretch);
}

}  // namespace

cl::Paths keepOutOf(const geometry::TriangleMesh& mesh, const Projection& projection, const std::vector<Band>& bands,
                    const Window& window, double tolerance, const cl::Paths& within) {
  // Where the centre goes nowhere (a level the tool fits nowhere in), nothing is kept out: the window of no
  // path is unbounded, not a rectangle.
  if (within.empty() || bands.empty()) return {};
  const Window box = windowAround(within, 1.0);
  const cl::Paths rectangle = {{{cl::cInt(box.x0), cl::cInt(box.y0)}, {cl::cInt(box.x1), cl::cInt(box.y0)},
                                {cl::cInt(box.x1), cl::cInt(box.y1)}, {cl::cInt(box.x0), cl::cInt(box.y1)}}};
  const Bins bins = projectedPieces(mesh, projection, bands, window,
                                    [&](const Eigen::Vector3d(&p)[3], const Eigen::Vector2d& least) { return keepOutClass(projection, p, least); });
  cl::Paths grown;
  for (const auto& [key, bin] : bins) {
    const Band& band = bands[static_cast<size_t>(key % kMaxBands)];
    const cl::Paths pieces = united(bin.pieces);
    cl::Paths part = boolean(cl::ctIntersection, grownBy(pieces, bin.scales, {band.clearance, band.clearance}, tolerance),
                             rectangle);
    // The pieces grown by the common part of the disk and the ellipse lie in both grown alike.
    if (const auto e = narrowerIn(band, static_cast<long long>(std::floor(bin.convexity / kConvexityStep))))
      part = boolean(cl::ctIntersection, part, grownBy(pieces, bin.scales, *e, tolerance));
    grown.insert(grown.end(), part.begin(), part.end());
  }
  // Not united: each bin's paths wind once round what they cover (holes cancel their own outline), so their
  // sum is non-zero exactly where some bin covers; the difference that uses them unites them on the way.
  return grown;
}

}  // namespace hsm::roughing
