// 2-D offsets, booleans and shadows of a level laid flat (flat.hpp), in Clipper's integers of 0.1 µm.
#include "roughing/flat.hpp"

#include <algorithm>
#include <cmath>
#include <map>

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

double distanceToBoundary(const cl::IntPoint& q, const cl::Paths& paths) {
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d p(double(q.X), double(q.Y));
  for (const cl::Path& path : paths)
    for (size_t i = 0; i < path.size(); ++i) {
      const Eigen::Vector2d a(double(path[i].X), double(path[i].Y));
      const cl::IntPoint& nb = path[(i + 1) % path.size()];
      const Eigen::Vector2d b(double(nb.X), double(nb.Y));
      const Eigen::Vector2d d = b - a;
      const double t = d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (a + t * d - p).norm());
    }
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

// The mesh's triangles laid flat, each cut to each band of `bands` (heights [from, to[) it meets, leaving out
// those outside `window`, split where the plane's scales vary over them, gathered in bins by
// `binOf(triangle, band)`: what stands over the surface, seen
// along the tool axis. The mesh is of closed solids, its triangles facing out: on planes only those facing the
// spindle are needed (a ray along the tool axis from any point of the solid leaves it through one of them),
// half the union's work. (Unrolled cylinders keep every triangle: culled there, S2's levels lost part of their
// region, 121 against 150 mm of cutting on an impeller channel, for a reason not found yet.)
// Whether the plane's scales differ by more than 15 % over the triangle's corners: its shadow, grown by one
// scale, would then be grown too much at its other end.
bool scalesVary(const Projection& projection, const Eigen::Vector3d (&p)[3]) {
  const Eigen::Vector2d s[3] = {projection.scalesAt(p[0]), projection.scalesAt(p[1]), projection.scalesAt(p[2])};
  const Eigen::Vector2d low = s[0].cwiseMin(s[1]).cwiseMin(s[2]), high = s[0].cwiseMax(s[1]).cwiseMax(s[2]);
  return high.x() > 1.15 * low.x() || high.y() > 1.15 * low.y();
}

template <class BinOf>
void addTriangle(const Projection& projection, const Eigen::Vector3d (&p)[3], const std::vector<Band>& bands,
                 const Window& window, int depth, BinOf& binOf, std::map<int, cl::Paths>& bins) {
  if (depth < 3 && scalesVary(projection, p)) {  // in four, by its edges' middles
    const Eigen::Vector3d m[3] = {0.5 * (p[0] + p[1]), 0.5 * (p[1] + p[2]), 0.5 * (p[2] + p[0])};
    const Eigen::Vector3d quarters[4][3] = {{p[0], m[0], m[2]}, {m[0], p[1], m[1]}, {m[2], m[1], p[2]}, {m[0], m[1], m[2]}};
    for (const auto& q : quarters) addTriangle(projection, q, bands, window, depth + 1, binOf, bins);
    return;
  }
  const double h[3] = {projection.height(p[0]), projection.height(p[1]), projection.height(p[2])};
  const double low = std::min({h[0], h[1], h[2]}), high = std::max({h[0], h[1], h[2]});
  for (size_t b = 0; b < bands.size(); ++b)
    if (high >= bands[b].from && low < bands[b].to)
      addProjected(projection, p, h, bands[b].from, bands[b].to, bins[binOf(p, static_cast<int>(b))]);
}

template <class BinOf>
std::map<int, cl::Paths> projectedPieces(const geometry::TriangleMesh& mesh, const Projection& projection,
                                         const std::vector<Band>& bands, const Window& window, BinOf&& binOf) {
  std::map<int, cl::Paths> bins;
  const double lowest = bands.front().from;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    const double h[3] = {projection.height(p[0]), projection.height(p[1]), projection.height(p[2])};
    if (!(std::max({h[0], h[1], h[2]}) >= lowest)) continue;
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (projection.cullsBackFaces() && normal.dot(projection.axisAt((p[0] + p[1] + p[2]) / 3.0)) <= 0.0) continue;
    if (projection.skip(p) || window.misses(projection.plane(p[0]), projection.plane(p[1]), projection.plane(p[2])))
      continue;
    addTriangle(projection, p, bands, window, 0, binOf, bins);
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
  return united(projectedPieces(mesh, projection, all, window, [](const Eigen::Vector3d(&)[3], int) { return 0; })[0]);
}

cl::Paths keepOutOf(const geometry::TriangleMesh& mesh, const Projection& projection, const std::vector<Band>& bands,
                    const Window& window, double tolerance, const cl::Paths& within) {
  // Where the centre goes nowhere (a level the tool fits nowhere in), nothing is kept out: the window of no
  // path is unbounded, not a rectangle.
  if (within.empty() || bands.empty()) return {};
  const Window box = windowAround(within, 1.0);
  const cl::Paths rectangle = {{{cl::cInt(box.x0), cl::cInt(box.y0)}, {cl::cInt(box.x1), cl::cInt(box.y0)},
                                {cl::cInt(box.x1), cl::cInt(box.y1)}, {cl::cInt(box.x0), cl::cInt(box.y1)}}};
  const double ratio = 1.05;
  auto level = [&](double scale) {
    return static_cast<int>(std::floor(std::log(std::clamp(scale, 1e-3, 1e3)) / std::log(ratio)));
  };
  constexpr int kLevels = 512;  // scale levels within ±142, bands below 16: one key
  const auto bins = projectedPieces(mesh, projection, bands, window, [&](const Eigen::Vector3d(&p)[3], int band) {
    const Eigen::Vector2d s = projection.scalesAt(p[0]).cwiseMin(projection.scalesAt(p[1])).cwiseMin(projection.scalesAt(p[2]));
    return (band * kLevels + level(s.x()) + kLevels / 2) * kLevels + level(s.y()) + kLevels / 2;
  });
  cl::Paths grown;
  for (const auto& [key, pieces] : bins) {
    const int band = key / (kLevels * kLevels), ix = (key / kLevels) % kLevels - kLevels / 2, iy = key % kLevels - kLevels / 2;
    const double sx = std::pow(ratio, ix), sy = std::pow(ratio, iy);
    // The least scales of the bin (its lower edges): x stretched by sx/sy makes the plane's metric sy both ways.
    const cl::Paths part = boolean(
        cl::ctIntersection,
        scaledX(offset(scaledX(united(pieces), sx / sy), bands[band].clearance / sy, tolerance), sy / sx), rectangle);
    grown.insert(grown.end(), part.begin(), part.end());
  }
  // Not united: each bin's paths wind once round what they cover (holes cancel their own outline), so their
  // sum is non-zero exactly where some bin covers; the difference that uses them unites them on the way.
  return grown;
}

}  // namespace hsm::roughing
