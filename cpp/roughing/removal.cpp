// Material removal by a tool swept through a tri-dexel model (removal.hpp).
#include "roughing/removal.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/dexel.hpp"
#include "roughing/triangle_grid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

namespace hsm::roughing {

namespace {

constexpr long kMaxRays = 20'000'000;  // three models of them: material, part, part not entered
constexpr long kMaxPositions = 10'000'000;
// Positions whose chips are tallied per lane before they are added up: bounds that memory (16 bytes per
// position and lane) however long the program.
constexpr size_t kRoundPositions = 1 << 15;
// Lanes of rows (at least; two per thread beyond): enough for the threads to share them out evenly, and the
// same for 1 to 4 threads, so that those add the lanes' chips up alike.
constexpr int kLanes = 8;
// Batches a thread cuts on a lane before it hands the lane back: a batch (5 mm of path) is little work, and a
// hand-over takes the lock and wakes the reporting thread (handing over each batch, two threads spent 17 % more
// CPU than one on the impeller's S1; every 64th, 3 %).
constexpr long kLaneSteps = 64;
// mm: a ray whose material ends this close to the cutter's bounding cylinder is still cut (the cutter's own
// spans are computed otherwise and may reach a rounding error beyond it).
constexpr double kSlack = 1e-9;
constexpr double kTieHair = 1e-9;  // mm: stick-outs this close are the same height read from another position
constexpr int kCornerSegments = 8;
constexpr double kRapidVolume = 1e-6;  // mm³: less is rounding at a grazing ray, not material  // a torus corner of radius 1 as 8 cones: within 5 µm of it

// The cutter as a solid of revolution about its axis (z up from the tip): cones (cylinders when r0 = r1)
// between heights h0 < h1, and spheres centred on the axis.
struct Cone {
  double h0, r0, h1, r1;
};
struct Ball {
  double centre, radius;
};
struct Shape {
  std::vector<Cone> cones;            // the flutes' cylinder first, then a torus's corner
  std::vector<Ball> balls;
  double radius = 0.0, length = 0.0;  // bounding cylinder
  double corner = 0.0;                // below this height the corner's cones and the ball are needed
  double top = 0.0;                   // the highest point of the cones and balls (above `length` when the
                                      // flutes are shorter than the corner)
  std::vector<int> stack;             // the cones from the bottom up
  bool flutes = false;                // cones[0] is the flutes' cylinder (radius, up to length)
};

Shape shapeOf(const Cutter& c) {
  Shape s;
  const double R = c.radius(), L = c.fluteLength;
  s.radius = R, s.length = L;
  if (c.kind == CutterKind::Flat) {
    s.cones.push_back({0.0, R, L, R});
  } else if (c.kind == CutterKind::Ball) {
    if (L > R) s.cones.push_back({R, R, L, R});
    s.balls.push_back({R, R});
    s.corner = R;
  } else {
    const double r = c.cornerRadius;
    if (L > r) s.cones.push_back({r, R, L, R});
    double h = 0.0, rho = R - r;
    for (int k = 1; k <= kCornerSegments; ++k) {
      const double phi = 0.5 * M_PI * k / kCornerSegments;
      const double h1 = r - r * std::cos(phi), rho1 = R - r + r * std::sin(phi);
      s.cones.push_back({h, rho, h1, rho1});
      h = h1, rho = rho1;
    }
    s.corner = r;
  }
  for (size_t c = 0; c < s.cones.size(); ++c) s.stack.push_back(static_cast<int>(c));
  std::sort(s.stack.begin(), s.stack.end(), [&](int a, int b) { return s.cones[a].h0 < s.cones[b].h0; });
  s.flutes = !s.cones.empty() && s.cones[0].r0 == R && s.cones[0].r1 == R && s.cones[0].h1 == L;
  s.top = s.length;
  for (const Cone& c : s.cones) s.top = std::max(s.top, c.h1);
  for (const Ball& b : s.balls) s.top = std::max(s.top, b.centre + b.radius);
  return s;
}

using Span = std::optional<Interval>;

Span intersect(Span a, double from, double to) {
  if (!a) return a;
  a->from = std::max(a->from, from), a->to = std::min(a->to, to);
  return a->to > a->from ? a : Span{};
}

// The ray q + t·d (tool frame) inside a cone: the slab of its heights, and within it the quadratic of the
// radius; a cone between two heights is convex, so at most one interval.
Span coneSpan(const Cone& c, const Eigen::Vector3d& q, const Eigen::Vector3d& d) {
  double s0 = -std::numeric_limits<double>::infinity(), s1 = -s0;
  if (std::abs(d.z()) < 1e-12) {
    if (q.z() < c.h0 || q.z() > c.h1) return {};
  } else {
    s0 = (c.h0 - q.z()) / d.z(), s1 = (c.h1 - q.z()) / d.z();
    if (s0 > s1) std::swap(s0, s1);
  }
  const double k = (c.r1 - c.r0) / (c.h1 - c.h0);
  const double c0 = c.r0 + k * (q.z() - c.h0), c1 = k * d.z();
  const double A = d.x() * d.x() + d.y() * d.y() - c1 * c1;
  const double B = 2.0 * (q.x() * d.x() + q.y() * d.y() - c0 * c1);
  const double C = q.x() * q.x() + q.y() * q.y() - c0 * c0;
  if (std::abs(A) < 1e-12) {
    if (std::abs(B) < 1e-12) return C <= 0.0 ? intersect(Interval{s0, s1}, s0, s1) : Span{};
    const double t = -C / B;
    return B > 0.0 ? intersect(Interval{s0, t}, s0, s1) : intersect(Interval{t, s1}, s0, s1);
  }
  const double disc = B * B - 4.0 * A * C;
  if (A > 0.0) {
    if (disc < 0.0) return {};
    const double root = std::sqrt(disc);
    return intersect(Interval{(-B - root) / (2.0 * A), (-B + root) / (2.0 * A)}, s0, s1);
  }
  if (disc < 0.0) return intersect(Interval{s0, s1}, s0, s1);  // inside everywhere within the slab
  const double root = std::sqrt(disc);
  const double t1 = (-B + root) / (2.0 * A), t2 = (-B - root) / (2.0 * A);  // t1 ≤ t2 (A < 0)
  const Span before = intersect(Interval{s0, t1}, s0, s1), after = intersect(Interval{t2, s1}, s0, s1);
  if (before && after) return Interval{before->from, after->to};
  return before ? before : after;
}

// 1 / 2A of radialSpan's quadratic, A = dx² + dy²: the same for every ray of a direction and a position, so
// each ray multiplies instead of dividing twice.
double halfInverseOfA(const Eigen::Vector3d& d) { return 0.5 / (d.x() * d.x() + d.y() * d.y()); }

// The ray q + t·d (tool frame) within `radius` of the tool's axis: coneSpan's quadratic with the slope 0, an
// interval unbounded where the ray runs along the axis; `halfInverse` is halfInverseOfA(d).
Span radialSpan(double radius, const Eigen::Vector3d& q, const Eigen::Vector3d& d, double halfInverse) {
  const double far = std::numeric_limits<double>::infinity();
  const double A = d.x() * d.x() + d.y() * d.y();  // ≥ 0
  const double B = 2.0 * (q.x() * d.x() + q.y() * d.y());
  const double C = q.x() * q.x() + q.y() * q.y() - radius * radius;
  if (A < 1e-12) {
    if (std::abs(B) < 1e-12) return C <= 0.0 ? Span{Interval{-far, far}} : Span{};
    const double t = -C / B;
    return B > 0.0 ? Interval{-far, t} : Interval{t, far};
  }
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return {};
  const double root = std::sqrt(disc);
  return Interval{(-B - root) * halfInverse, (-B + root) * halfInverse};
}

// A radialSpan cut to the heights 0 to `height`: the span of a cylinder of the cutter's radius (the bounding
// one up to the flutes' length, a taller one up to the cutter's top), the same numbers as coneSpan's with fewer
// operations; the two cylinders of a ray share their radialSpan.
Span heightSpan(const Span& radial, double height, const Eigen::Vector3d& q, const Eigen::Vector3d& d) {
  if (!radial) return radial;
  double s0 = -std::numeric_limits<double>::infinity(), s1 = -s0;
  if (std::abs(d.z()) < 1e-12) {
    if (q.z() < 0.0 || q.z() > height) return {};
  } else {
    s0 = (0.0 - q.z()) / d.z(), s1 = (height - q.z()) / d.z();
    if (s0 > s1) std::swap(s0, s1);
  }
  return intersect(radial, s0, s1);
}

// coneSpan of the flutes' cylinder (the cutter's radius from height h0 up to the flutes' length) from the
// bounding cylinder's span along the same ray: the same roots, cut where coneSpan cuts them at h0.
Span flutesSpan(double h0, const Interval& bound, const Eigen::Vector3d& q, const Eigen::Vector3d& d) {
  if (std::abs(d.z()) < 1e-12) return q.z() < h0 ? Span{} : Span{bound};
  const double s = (h0 - q.z()) / d.z(), far = std::numeric_limits<double>::infinity();
  return d.z() > 0.0 ? intersect(bound, s, far) : intersect(bound, -far, s);
}

Span ballSpan(const Ball& b, const Eigen::Vector3d& q, const Eigen::Vector3d& d) {
  const Eigen::Vector3d w = q - Eigen::Vector3d(0.0, 0.0, b.centre);
  const double half = w.dot(d), disc = half * half - (w.squaredNorm() - b.radius * b.radius);
  if (disc < 0.0) return {};
  const double root = std::sqrt(disc);
  return Interval{-half - root, -half + root};
}

// The distance between the positions sampled along a move: a ridge of s²/8r ≤ resolution/4 between the
// scallops of the cutter's corner (its radius for a flat end), and at most 4 resolutions.
double sampleStep(const Cutter& c, double resolution) {
  const double corner = c.kind == CutterKind::Torus ? c.cornerRadius : c.radius();
  return std::min(4.0 * resolution, std::sqrt(2.0 * std::max(corner, resolution) * resolution));
}

// One position of the tool: its tip, its frame (axis last) and its box.
struct Position {
  Eigen::Vector3d tip, e1, e2, axis;
  Eigen::AlignedBox3d box;
  double step = 0.0;  // mm of the tip's path since the position before
  double along = 0.0;  // share of its move's length at the position before this one (where it did not cut yet)
  int move = 0;
  bool feed = false;
};

Position positionAt(const Eigen::Vector3d& tip, const Eigen::Vector3d& axis, const Shape& shape) {
  Position p;
  p.tip = tip;
  p.axis = axis.normalized();
  p.e1 = p.axis.unitOrthogonal();
  p.e2 = p.axis.cross(p.e1);
  const Eigen::Vector3d top = tip + shape.length * p.axis;
  Eigen::Vector3d reach;
  for (int k = 0; k < 3; ++k) reach[k] = shape.radius * std::sqrt(std::max(0.0, 1.0 - p.axis[k] * p.axis[k]));
  p.box = Eigen::AlignedBox3d(tip.cwiseMin(top) - reach, tip.cwiseMax(top) + reach);
  return p;
}

// Cone c's span along the ray q + t·d, or none without solving where the ray keeps out of it: farther from
// the axis than its widest circle, or beyond its heights within the bounding cylinder (`low` to `high`).
Span coneSpanNear(const Shape& shape, int c, const Interval& bound, double low, double high, const Eigen::Vector3d& q,
                  const Eigen::Vector3d& d) {
  const Cone& cone = shape.cones[c];
  if (cone.h0 > high + kSlack || cone.h1 < low - kSlack) return {};
  // The ray's least distance from the axis, squared, is cross² / dxy (|q| across it for a ray along it).
  const double dxy = d.x() * d.x() + d.y() * d.y(), cross = q.x() * d.y() - q.y() * d.x();
  const double widest = std::max(cone.r0, cone.r1) + kSlack;
  if (dxy > 0.0 ? widest * widest * dxy < cross * cross : widest * widest < q.x() * q.x() + q.y() * q.y()) return {};
  return c == 0 && shape.flutes ? flutesSpan(cone.h0, bound, q, d) : coneSpan(cone, q, d);
}

// A cutter of cones only (flat, torus) is convex: its profile's radius grows ever slower with height, from
// the flat bottom up the corner to the flutes' cylinder. Along a ray whose height changes, its cones' spans
// then follow one another in the order of their heights and join into one; so only the first and the last
// the ray meets are computed, walking in from both ends of the stack (in the corner most rays meet few of
// its eight cones). False where that does not hold (a ball, a ray at one height): every span is computed.
bool walkStack(const Shape& shape, const Eigen::Vector3d& q, const Eigen::Vector3d& d, const Interval& bound,
               Intervals& out) {
  if (!shape.balls.empty() || std::abs(d.z()) < 1e-12) return false;
  const int n = static_cast<int>(shape.stack.size());
  const double z0 = q.z() + bound.from * d.z(), z1 = q.z() + bound.to * d.z();
  const double low = std::min(z0, z1), high = std::max(z0, z1);
  const auto spanOf = [&](int m) {
    return coneSpanNear(shape, shape.stack[d.z() > 0.0 ? m : n - 1 - m], bound, low, high, q, d);
  };
  Span first, last;
  int m = 0;
  while (m < n && !(first = spanOf(m))) ++m;
  if (!first) return true;
  for (int e = n - 1; e > m && !last; --e) last = spanOf(e);
  out.push_back({first->from, last ? last->to : first->to});
  return true;
}

// The cutter's intervals along the ray q + t·d (tool frame), united (sorted, merged); `bound`: the ray within
// the bounding cylinder (the caller's test that it meets the tool at all).
void cutterSpans(const Shape& shape, const Eigen::Vector3d& q, const Eigen::Vector3d& d, const Interval& bound,
                 Intervals& out) {
  out.clear();
  const bool low = std::min(q.z() + bound.from * d.z(), q.z() + bound.to * d.z()) < shape.corner;
  if (low && walkStack(shape, q, d, bound, out)) return;
  for (size_t c = 0; c < shape.cones.size(); ++c)
    if (c == 0 || low)
      if (const Span s = c == 0 && shape.flutes ? flutesSpan(shape.cones[0].h0, bound, q, d) : coneSpan(shape.cones[c], q, d))
        out.push_back(*s);
  if (low)
    for (const Ball& b : shape.balls)
      if (const Span s = ballSpan(b, q, d)) out.push_back(*s);
  if (out.size() < 2) return;
  std::sort(out.begin(), out.end(), [](const Interval& a, const Interval& b) { return a.from < b.from; });
  size_t n = 0;
  for (size_t i = 1; i < out.size(); ++i) {
    if (out[i].from <= out[n].to + 1e-12) out[n].to = std::max(out[n].to, out[i].to);
    else out[++n] = out[i];
  }
  out.resize(n + 1);
}

bool touches(const Intervals& ray, double from, double to) {
  for (const Interval& s : ray)
    if (s.to > from && s.from < to) return true;
  return false;
}

// Whether ray (i, j) of direction k of `model`, whose extent is e, has material within ]from, to[: the extent
// first, which most rays fail without their intervals being read.
bool meets(const TriDexel& model, const TriDexel::Extent& e, int k, int i, int j, double from, double to) {
  return e.to > from && e.from < to && touches(model.at(k, i, j), from, to);
}

// The first and the last index of a range [lo, hi] from a double (perhaps far out): none when first > last.
int firstWithin(double x, int lo, int hi) { return static_cast<int>(std::clamp(x, double(lo), hi + 1.0)); }
int lastWithin(double x, int lo, int hi) { return static_cast<int>(std::clamp(x, lo - 1.0, double(hi))); }

// The u-range [from, to] of the points (u, c) within `radius` of the segment a-b (2-D; from > to: none). Seen
// along a model's rays, a cylinder about a segment lies within this capsule: the rays of row c that can meet it.
std::pair<double, double> rowOfCapsule(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double radius, double c) {
  double from = std::numeric_limits<double>::infinity(), to = -from;
  const auto add = [&](double u) { from = std::min(from, u), to = std::max(to, u); };
  for (const Eigen::Vector2d* end : {&a, &b}) {  // the round ends
    const double across = radius * radius - (c - end->y()) * (c - end->y());
    if (across >= 0.0) add(end->x() - std::sqrt(across)), add(end->x() + std::sqrt(across));
  }
  const Eigen::Vector2d along = b - a;
  const double length = along.norm();
  if (length > 0.0) {
    const Eigen::Vector2d side = radius / length * Eigen::Vector2d(-along.y(), along.x());
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(a + side), Eigen::Vector2d(a - side)}) {  // the straight sides
      const Eigen::Vector2d q = p + along;
      if (p.y() != q.y() && (p.y() - c) * (q.y() - c) <= 0.0) add(p.x() + (c - p.y()) / (q.y() - p.y()) * (q.x() - p.x()));
    }
  }
  return {from, to};
}

// Samples of the moves: the tip straight, the axis turned evenly, neighbours at most `step` apart at the tip
// and at the flutes' end.
std::vector<Position> positionsOf(const std::vector<ToolMove>& moves, const Shape& shape, double step) {
  std::vector<Position> out;
  if (moves.empty()) return out;
  long total = 1;
  for (size_t i = 1; i < moves.size(); ++i) {
    const double turn = std::acos(std::clamp(moves[i].axis.normalized().dot(moves[i - 1].axis.normalized()), -1.0, 1.0));
    total += 1 + static_cast<long>(std::max((moves[i].tip - moves[i - 1].tip).norm(), turn * shape.length) / step);
    if (total > kMaxPositions)
      throw InputError("material removal: the moves need more than " + std::to_string(kMaxPositions) +
                       " tool positions at this resolution: use a coarser resolution");
  }
  out.reserve(static_cast<size_t>(total));
  out.push_back(positionAt(moves[0].tip, moves[0].axis, shape));
  out.back().feed = moves[0].kind != MoveKind::Rapid;
  for (size_t i = 1; i < moves.size(); ++i) {
    const ToolMove& a = moves[i - 1];
    const ToolMove& b = moves[i];
    const double turn = std::acos(std::clamp(b.axis.normalized().dot(a.axis.normalized()), -1.0, 1.0));
    const double length = (b.tip - a.tip).norm();
    const int n = 1 + static_cast<int>(std::max(length, turn * shape.length) / step);
    for (int k = 1; k <= n; ++k) {
      const double f = double(k) / n;
      Position p = positionAt(a.tip + f * (b.tip - a.tip), (1.0 - f) * a.axis.normalized() + f * b.axis.normalized(), shape);
      p.step = length / n;
      p.along = double(k - 1) / n;
      p.move = static_cast<int>(i);
      p.feed = b.kind != MoveKind::Rapid;
      out.push_back(p);
    }
  }
  return out;
}

// Where the thickness of stock on the part is read for a vertex: a ray of the direction nearest its normal,
// the part's crossing on it and the side the stock lies.
struct Sample {
  int k = -1, i = 0, j = 0;
  double surface = 0.0;  // coordinate along the ray of the part's crossing
  bool after = true;     // the stock lies at larger coordinates
  double cosine = 1.0, weight = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

double stockAt(const TriDexel& material, const Sample& s) {
  for (const Interval& m : material.at(s.k, s.i, s.j)) {
    if (s.after && std::abs(m.from - s.surface) < 1e-9) return (m.to - m.from) * s.cosine;
    if (!s.after && std::abs(m.to - s.surface) < 1e-9) return (m.to - m.from) * s.cosine;
  }
  return 0.0;
}

// A sample of the part's surface at p (normal n outward, standing for `weight` mm²), or none where no ray of
// the model meets the part there or no stock stood on it to begin with (a face on the stock's skin).
std::optional<Sample> sampleAt(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double weight,
                               const TriDexel& partModel, const TriDexel& material) {
  const double h = partModel.resolution();
  Sample s;
  n.cwiseAbs().maxCoeff(&s.k);
  int i0, i1, j0, j1;
  partModel.rangeOf(s.k, Eigen::AlignedBox3d(p - Eigen::Vector3d::Constant(0.5 * h), p + Eigen::Vector3d::Constant(0.5 * h)),
                    i0, i1, j0, j1);
  if (i0 > i1 || j0 > j1) return {};
  s.i = i0, s.j = j0, s.after = n[s.k] > 0.0, s.cosine = std::abs(n[s.k]);
  // The part's crossing on that ray nearest the point, on the side the normal points to.
  double best = std::numeric_limits<double>::infinity();
  for (const Interval& m : partModel.at(s.k, s.i, s.j)) {
    const double x = s.after ? m.to : m.from;
    if (std::abs(x - p[s.k]) < best) best = std::abs(x - p[s.k]), s.surface = x;
  }
  if (!(best < 2.0 * h / std::max(s.cosine, 0.3)) || stockAt(material, s) <= 0.0) return {};
  s.weight = weight;
  s.point = p;
  return s;
}

// The samples on triangle t of the mesh, `spacing` apart, added to `out`.
void samplesOn(const geometry::TriangleMesh& mesh, const Eigen::Vector3i& t, double spacing, const TriDexel& partModel,
               const TriDexel& material, std::vector<Sample>& out) {
  const Eigen::Vector3d& a = mesh.vertices[t[0]];
  const Eigen::Vector3d& b = mesh.vertices[t[1]];
  const Eigen::Vector3d& c = mesh.vertices[t[2]];
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  if (!(normal.norm() > 0.0)) return;
  const int m = std::max(1, static_cast<int>(std::ceil(std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()}) / spacing)));
  const double weight = 0.5 * normal.norm() / (m * m);
  auto add = [&](double u, double v) {
    if (auto s = sampleAt(a + u * (b - a) + v * (c - a), normal.normalized(), weight, partModel, material))
      out.push_back(*s);
  };
  for (int i = 0; i < m; ++i)
    for (int j = 0; i + j < m; ++j) {
      add((i + 1.0 / 3.0) / m, (j + 1.0 / 3.0) / m);
      if (i + j + 2 <= m) add((i + 2.0 / 3.0) / m, (j + 2.0 / 3.0) / m);
    }
}

// Samples of the part's surface about two resolutions apart (at most 2 million: farther apart on a large
// part), at the centres of each triangle's subdivision: in chunks of triangles on `threads` threads, each
// chunk's in the triangles' order.
std::vector<std::vector<Sample>> samplesOf(const geometry::TriangleMesh& mesh, const TriDexel& partModel,
                                           const TriDexel& material, int threads) {
  double area = 0.0;
  for (const Eigen::Vector3i& t : mesh.triangles)
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
  const double spacing = std::max(2.0 * partModel.resolution(), std::sqrt(area / 1e6));
  const long triangles = static_cast<long>(mesh.triangles.size()), chunk = 2048;
  std::vector<std::vector<Sample>> chunks(static_cast<size_t>((triangles + chunk - 1) / chunk));
  parallelChunks(triangles, threads, chunk, [&](long from, long to) {
    for (long t = from; t < to; ++t) samplesOn(mesh, mesh.triangles[t], spacing, partModel, material, chunks[from / chunk]);
  });
  return chunks;
}

// The stock's and the part's meshes at `deflection`, side by side when there are two threads or more (OCCT
// meshes the part's many faces in parallel itself, but the stock's few faces would be meshed alone).
std::array<geometry::TriangleMesh, 2> meshesOf(const TopoDS_Shape& stock, const TopoDS_Shape& part, double deflection,
                                               int threads) {
  std::array<geometry::TriangleMesh, 2> meshes;
  parallelChunks(2, threads, 1, [&](long from, long to) {
    for (long m = from; m < to; ++m) meshes[m] = geometry::meshFacesAfresh(m == 0 ? stock : part, deflection);
  });
  return meshes;
}

class Simulation {
public:
  Simulation(const TopoDS_Shape& stock, const TopoDS_Shape& part, const RemovalSettings& settings)
      : Simulation(settings, meshesOf(stock, part, deflection(settings.resolution), threadCount(settings.threads))) {}

  // The models' rays are freed by the thread that ends the simulation, not side by side: a ray's memory was
  // taken by the thread that filled it, and glibc frees it into that thread's arena under its lock, so two
  // threads freeing the same models took 0.05 s where one takes 0.03 (the impeller at 0.2 mm).

  RemovalResult run(const std::vector<ToolRun>& runs) {
    RemovalResult r;
    r.resolution = settings_.resolution;
    r.rays = material_.rays();
    r.volumeToRemove = material_.volume();
    const std::vector<std::vector<Sample>> samples = samplesOf(partMesh_, part_, material_, threads_);
    const double h = settings_.resolution;
    std::vector<std::vector<Position>> positionsOfRuns;
    long total = 0;
    int offset = 0;  // the runs' moves count on through all of them
    for (const ToolRun& run : runs) {
      positionsOfRuns.push_back(positionsOf(run.moves, shapeOf(run.cutter), sampleStep(run.cutter, h)));
      for (Position& p : positionsOfRuns.back()) p.move += offset;
      offset += static_cast<int>(run.moves.size());
      total += static_cast<long>(positionsOfRuns.back().size());
      if (total > kMaxPositions)
        throw InputError("material removal: the moves need more than " + std::to_string(kMaxPositions) +
                         " tool positions at this resolution: use a coarser resolution");
      for (size_t i = 1; i < run.moves.size(); ++i) {
        const double length = (run.moves[i].tip - run.moves[i - 1].tip).norm();
        r.pathLength += length;
        if (run.moves[i].kind != MoveKind::Rapid) r.feedLength += length;
      }
    }
    r.positions = total;
    ProgressReporter report(settings_.progress, "material removal");
    long before = 0;  // positions of the runs done
    for (size_t k = 0; k < runs.size(); ++k) {
      shape_ = shapeOf(runs[k].cutter), cutter_ = runs[k].cutter;
      cutRun(positionsOfRuns[k], r, [&](size_t done) { report(double(before + long(done)) / double(std::max(1L, total))); });
      before += static_cast<long>(positionsOfRuns[k].size());
    }
    r.remainingVolume = material_.volume();
    r.remainingShare = r.volumeToRemove > 0.0 ? 100.0 * r.remainingVolume / r.volumeToRemove : 0.0;
    r.inMaterialShare = r.feedLength > 0.0 ? 100.0 * r.inMaterialLength / r.feedLength : 0.0;
    r.inMaterialPathShare = r.pathLength > 0.0 ? 100.0 * r.inMaterialLength / r.pathLength : 0.0;
    thicknessOf(samples, r);
    double layer = 0.0;
    for (size_t i = 0; i < r.thickness.size(); ++i) layer += r.weight[i] * std::min(r.thickness[i], settings_.allowance);
    r.beyondAllowanceVolume = std::max(0.0, r.remainingVolume - layer);
    r.beyondAllowanceShare = r.volumeToRemove > 0.0 ? 100.0 * r.beyondAllowanceVolume / r.volumeToRemove : 0.0;
    if (settings_.stockMeshStride > 0) r.stockMesh = material_.blocks(settings_.stockMeshStride);
    if (settings_.restSpacing > 0.0) r.rest = restOf();
    return r;
  }

private:
  // One tool's positions through the model, in rounds of batches (a batch ends where the stick-out is measured
  // next); `report` is told how many of them are done.
  template <class Report>
  void cutRun(const std::vector<Position>& positions, RemovalResult& r, Report&& report) {
    const std::vector<size_t> ends = batchEnds(positions);
    for (size_t first = 0; first < ends.size();) {
      const size_t start = first ? ends[first - 1] : 0;
      size_t last = first + 1;
      while (last < ends.size() && ends[last] - start <= kRoundPositions) ++last;
      cutRound(positions, ends, first, last, r, report);
      first = last;
    }
  }

  Simulation(const RemovalSettings& settings, std::array<geometry::TriangleMesh, 2>&& meshes)
      : settings_(settings), threads_(threadCount(settings.threads)),
        lanes_(std::max(kLanes, 2 * threads_)),
        stockMesh_(std::move(meshes[0])), partMesh_(std::move(meshes[1])), stockBox_(stockMesh_.bounds()),
        material_(stockBox_, settings.resolution, kMaxRays / 2), part_(stockBox_, settings.resolution, kMaxRays / 2),
        uncut_(stockBox_, settings.resolution, kMaxRays / 2) {
    if (stockMesh_.triangles.empty()) throw InputError("material removal: the stock has no faces");
    material_.fill(stockMesh_, threads_);
    part_.fill(partMesh_, threads_);
    material_.subtract(part_, threads_);
    uncut_.assign(part_, threads_);
  }

  // The stock left farther from the part than the allowance and half a spacing, at points of every
  // stride-th Z ray each way, `stride` resolutions apart along it.
  RestStock restOf() const {
    constexpr long kMaxRestPoints = 5'000'000;
    const int stride = std::max(1, static_cast<int>(std::lround(settings_.restSpacing / material_.resolution())));
    RestStock rest;
    rest.spacing = stride * material_.resolution();
    const TriangleGrid grid(partMesh_, 2.0);
    std::vector<int> seen(partMesh_.triangles.size(), -1);
    int stamp = 0;
    const double keep = settings_.allowance + 0.5 * rest.spacing;
    for (int j = stride / 2; j < material_.count(2, 1); j += stride)
      for (int i = stride / 2; i < material_.count(2, 0); i += stride)
        for (const Interval& s : material_.at(2, i, j))
          for (double z = s.from + 0.5 * rest.spacing; z < s.to; z += rest.spacing) {
            Eigen::Vector3d p = material_.origin(2, i, j);
            p.z() = z;
            if (distanceToMesh(grid, partMesh_, p, keep, seen, stamp++) < keep) continue;
            rest.points.push_back(p);
            if (static_cast<long>(rest.points.size()) > kMaxRestPoints)
              throw InputError("material removal: more than " + std::to_string(kMaxRestPoints) + " points of stock left " +
                               "at a rest spacing of " + number(rest.spacing) + " mm: use a larger spacing");
          }
    return rest;
  }

  // `value` into `most` unless `most` is already as high (lanes on other threads raise it too).
  static void raise(std::atomic<double>& most, double value) {
    double seen = most.load(std::memory_order_relaxed);
    while (value > seen && !most.compare_exchange_weak(seen, value, std::memory_order_relaxed)) {
    }
  }

  static double deflection(double resolution) { return std::clamp(0.25 * resolution, 0.005, 0.05); }

  // Where a position's cutter lies seen along the rays of one direction (cutBatch's scratch).
  struct Reach {
    int i0 = 0, i1 = -1, j0 = 0, j1 = -1;  // the rays of its box
    int first = 0, last = -1;              // the rays of the current row within its capsule
    Eigen::Vector3d d;                     // the rays' direction in the tool's frame
    double halfInverseOfA = 0.0;           // of d: radialSpan's 1 / 2A
    Eigen::Vector2d tip, top;              // its axis, from the tip to the top of the cutter
  };

  // What a lane tallies for the positions of a round, on its own rows.
  struct alignas(64) Tally {  // a cache line of its own: lanes on other cores write theirs
    std::vector<double> removed, gouged;  // per position: length taken out along the Z rays, of stock and part
    std::vector<double> highest;          // per batch: the stick-out its rows need at the batch's end, or
                                          // `known` when that is more
    // The most any batch before needed (the lane's own, the rounds' before): a batch that needs no more cannot
    // raise the result, so its rays are only read where they would go higher (every batch still gets its
    // exact stick-out wherever it raises the most so far, so the result and its move do not change).
    double known = 0.0;
    Intervals spans;                      // scratch
    std::vector<Reach> reach;             // scratch
  };

  // The ends of the batches of positions: a batch ends where the stick-out is measured next (and at the last
  // position), so that it sees the stock as it is there.
  std::vector<size_t> batchEnds(const std::vector<Position>& positions) const {
    std::vector<size_t> ends;
    for (size_t end = 0; end < positions.size();) {
      double since = 0.0;
      const size_t start = end;
      while (end < positions.size() && (since < settings_.stickOutSpacing || end == start)) since += positions[end++].step;
      ends.push_back(end);
    }
    return ends;
  }

  // A lane owns pairs of rows dealt out in turn: the few rows a tool crosses are spread over all lanes, and so
  // are the stick-out's every other row. Each ray is cut by one lane only, in the positions' order, so lanes
  // need neither locks nor a barrier between positions. The first row from j on that `lane` owns (of j's
  // parity when `parity`: the stick-out's every other row).
  int nextRow(int lane, int j, bool parity = false) const {
    const int pair = j / 2, ahead = ((lane - pair) % lanes_ + lanes_) % lanes_;
    return ahead == 0 ? j : 2 * (pair + ahead) + (parity ? j % 2 : 0);
  }

  // Batches [first, last) of the positions through the model, each lane on its rows, then the chips, gouges,
  // rapid faults and stick-outs added up in the positions' order; `report` told the positions done.
  template <class Report>
  void cutRound(const std::vector<Position>& positions, const std::vector<size_t>& ends, size_t first, size_t last,
                RemovalResult& r, Report& report) {
    const size_t start = first ? ends[first - 1] : 0, n = ends[last - 1] - start;
    std::vector<Tally> tallies(static_cast<size_t>(lanes_));
    for (Tally& t : tallies) {
      t.removed.assign(n, 0.0), t.gouged.assign(n, 0.0), t.highest.assign(last - first, 0.0);
      t.known = r.stickOut;
    }
    // The most any lane has found so far, of any batch, earlier or later: a batch whose rows need less cannot
    // be the first to need the result, so it reads rays only above it (less a hair, so that a batch tying the
    // result, as every level under the blank's flat top does, still finds its exact value and keeps its move).
    std::atomic<double> found{r.stickOut};
    parallelLanes(
        lanes_, threads_, static_cast<long>(last - first),
        [&](int lane, long batch) {
          Tally& t = tallies[static_cast<size_t>(lane)];
          const size_t from = first + batch ? ends[first + batch - 1] : 0, to = ends[first + batch];
          cutBatch(positions, from, to, lane, t, start);
          const double floor = std::max(t.known, found.load(std::memory_order_relaxed) - kTieHair);
          const double needed = stickOutAt(positions[to - 1], lane, floor);
          if (needed > floor) t.known = std::max(t.known, needed), raise(found, needed);
          t.highest[static_cast<size_t>(batch)] = needed > floor ? needed : t.known;
        },
        [&](long done) { report(ends[first + done - 1]); }, kLaneSteps);
    const double cell = material_.resolution() * material_.resolution();
    for (size_t p = 0; p < n; ++p) {
      double volume = 0.0, gouge = 0.0;
      for (const Tally& t : tallies) volume += t.removed[p] * cell, gouge += t.gouged[p] * cell;
      const Position& at = positions[start + p];
      if (at.feed && at.step > 0.0 && volume >= settings_.chipSection * at.step) r.inMaterialLength += at.step;
      if (gouge > 0.0) {
        if (r.gougeMove < 0) r.gougeMove = at.move, r.gougeAt = at.tip;
        r.gougeVolume += gouge;
      }
      if (!at.feed && volume > kRapidVolume) {
        if (r.rapidFaults.empty() || r.rapidFaults.back().move != at.move)
          r.rapidFaults.push_back({at.move, at.tip, at.along, 0.0});
        r.rapidFaults.back().volume += volume;
        r.rapidVolume += volume;
      }
    }
    for (size_t b = first; b < last; ++b) {
      double needed = 0.0;
      for (const Tally& t : tallies) needed = std::max(needed, t.highest[b - first]);
      if (needed > r.stickOut) r.stickOut = needed, r.stickOutMove = positions[ends[b] - 1].move;
    }
  }

  // Positions [from, to) (a batch) through the rays of `lane`'s rows, ray by ray: only the rays within the
  // capsule about a cutter (not its whole box: a tilted tool's box is mostly empty), of those only the ones
  // whose stock or part reaches into its bounding cylinder. The batch's cutters overlap: a ray none of them can
  // take material from is looked at once for them all; each ray still meets the positions in their order, so
  // it loses what it would position by position, and each position adds up the Z rays' lengths it takes out
  // of the stock and of the part (tally indices from `start`) in the same order.
  void cutBatch(const std::vector<Position>& positions, size_t from, size_t to, int lane, Tally& t, size_t start) {
    const double h = material_.resolution();
    const double radius = shape_.radius * (1.0 + 1e-9) + kSlack;
    std::vector<Reach>& reach = t.reach;
    reach.resize(to - from);
    for (int k = 0; k < 3; ++k) {
      const int u = (k + 1) % 3, v = (k + 2) % 3;
      int rowFrom = std::numeric_limits<int>::max(), rowTo = -1;
      double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;  // the boxes along the rays
      for (size_t p = from; p < to; ++p) {
        const Position& at = positions[p];
        Reach& c = reach[p - from];
        material_.rangeOf(k, at.box, c.i0, c.i1, c.j0, c.j1);
        if (c.i0 > c.i1 || c.j0 > c.j1) continue;
        const Eigen::Vector3d top = at.tip + shape_.top * at.axis;
        c.d = Eigen::Vector3d(at.e1[k], at.e2[k], at.axis[k]);
        c.halfInverseOfA = halfInverseOfA(c.d);
        c.tip = Eigen::Vector2d(at.tip[u], at.tip[v]), c.top = Eigen::Vector2d(top[u], top[v]);
        rowFrom = std::min(rowFrom, c.j0), rowTo = std::max(rowTo, c.j1);
        lowest = std::min(lowest, at.box.min()[k]), highest = std::max(highest, at.box.max()[k]);
      }
      if (rowFrom > rowTo) continue;
      for (int j = nextRow(lane, rowFrom); j <= rowTo; j = nextRow(lane, j + 1)) {
        const Eigen::Vector3d row = material_.origin(k, 0, j);
        int first = std::numeric_limits<int>::max(), last = -1;
        for (Reach& c : reach) {
          c.first = 1, c.last = 0;
          if (c.i0 > c.i1 || j < c.j0 || j > c.j1) continue;
          const auto [ends, endsTo] = rowOfCapsule(c.tip, c.top, radius, row[v]);
          if (!(ends <= endsTo)) continue;
          c.first = firstWithin(std::ceil((ends - row[u]) / h), c.i0, c.i1);
          c.last = lastWithin(std::floor((endsTo - row[u]) / h), c.i0, c.i1);
          if (c.first <= c.last) first = std::min(first, c.first), last = std::max(last, c.last);
        }
        const TriDexel::Extent* stockRow = material_.extents(k, j);
        const TriDexel::Extent* partRow = k == 2 ? uncut_.extents(k, j) : nullptr;
        Eigen::Vector3d o = row;
        for (int i = first; i <= last; ++i) {
          // Most rays the tools cross lost their material there to the positions before: the boxes tell them
          // at once (by the extent: without reading the ray); each box then, and each bounding cylinder.
          if (!(partRow && partRow[i].to > lowest && partRow[i].from < highest) &&
              !(stockRow[i].to > lowest && stockRow[i].from < highest))
            continue;
          o[u] = material_.across(k, i);
          for (size_t p = from; p < to; ++p) {
            const Reach& c = reach[p - from];
            if (i < c.first || i > c.last) continue;
            const Position& at = positions[p];
            const double boxFrom = at.box.min()[k], boxTo = at.box.max()[k];
            if (!(partRow && meets(uncut_, partRow[i], k, i, j, boxFrom, boxTo)) &&
                !meets(material_, stockRow[i], k, i, j, boxFrom, boxTo))
              continue;
            const Eigen::Vector3d w = o - at.tip;
            const Eigen::Vector3d q(w.dot(at.e1), w.dot(at.e2), w.dot(at.axis));
            const Span across = radialSpan(shape_.radius, q, c.d, c.halfInverseOfA);
            const Span bound = heightSpan(across, shape_.length, q, c.d);
            if (!bound) continue;
            // Every span of the cutter lies within `within` (the bounding cylinder, or a taller one when the
            // corner stands above short flutes): a ray whose stock and part keep out of it loses nothing.
            const Span within = shape_.top > shape_.length ? heightSpan(across, shape_.top, q, c.d) : bound;
            const double lo = (within ? within : bound)->from - kSlack, hi = (within ? within : bound)->to + kSlack;
            const bool inPart = partRow && meets(uncut_, partRow[i], k, i, j, lo, hi);
            if (!inPart && !meets(material_, stockRow[i], k, i, j, lo, hi)) continue;
            cutterSpans(shape_, q, c.d, *bound, t.spans);
            for (const Interval& s : t.spans) {
              const double taken = material_.remove(k, i, j, s.from, s.to);
              if (k == 2) {
                t.removed[p - start] += taken;
                if (inPart) t.gouged[p - start] += uncut_.remove(k, i, j, s.from, s.to);
              }
            }
          }
        }
      }
    }
  }

  // The highest point of the part or of the stock left within the holder's radius of the axis, above the tip,
  // on `lane`'s rows, or `known` when none is higher: read on the rays of the direction nearest the axis, each
  // clipped to the holder's cylinder (rows clipped to the band that cylinder covers seen along them).
  double stickOutAt(const Position& at, int lane, double known) const {
    int k;
    at.axis.cwiseAbs().maxCoeff(&k);
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    const double radius = 0.5 * cutter_.holderDiameter;
    double reach = 0.0;  // how far up the axis the stock goes
    for (int c = 0; c < 8; ++c) reach = std::max(reach, (stockBox_.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - at.tip).dot(at.axis));
    if (reach <= known) return known;
    Eigen::Vector3d across;
    for (int a = 0; a < 3; ++a) across[a] = radius * std::sqrt(std::max(0.0, 1.0 - at.axis[a] * at.axis[a]));
    const Eigen::Vector3d top = at.tip + reach * at.axis;
    const Eigen::AlignedBox3d box(at.tip.cwiseMin(top) - across, at.tip.cwiseMax(top) + across);
    int i0, i1, j0, j1;
    material_.rangeOf(k, box, i0, i1, j0, j1);
    // A ray along e_k meets the axis's infinite cylinder where its distance to the axis, |(o - tip)·n| / |n|
    // with n = e_k × axis, is at most the radius: a band of each row (when the axis leans enough to tell).
    const Eigen::Vector3d n = Eigen::Vector3d::Unit(k).cross(at.axis);
    const double band = radius * n.norm() + kSlack;
    const double h = material_.resolution();
    double highest = known;
    for (int j = nextRow(lane, j0, true); j <= j1; j = nextRow(lane, j + 2, true)) {
      int first = i0, last = i1;
      if (n.norm() > 1e-3) {
        const Eigen::Vector3d row = material_.origin(k, 0, j);
        const double offset = (row[v] - at.tip[v]) * n[v];
        if (std::abs(n[u]) > 1e-9) {
          double from = at.tip[u] + (-band - offset) / n[u], to = at.tip[u] + (band - offset) / n[u];
          if (from > to) std::swap(from, to);
          first = firstWithin(i0 + 2.0 * std::ceil(std::max(0.0, from - row[u] - i0 * h) / (2.0 * h)), i0, i1);  // i0's parity
          last = lastWithin(std::floor((to - row[u]) / h), i0, i1);
        } else if (std::abs(offset) > band) {
          continue;
        }
      }
      for (int i = first; i <= last; i += 2) {  // every other ray: heights stay exact along each ray
        const Eigen::Vector3d o = material_.origin(k, i, j);
        const Eigen::Vector3d w = o - at.tip;
        // The extents bound what the ray can add, the height being linear along it: most rays cannot beat the
        // highest point found, and are neither clipped to the holder nor read.
        const TriDexel::Extent stockSpan = material_.extent(k, i, j), partSpan = part_.extent(k, i, j);
        const auto beats = [&](const TriDexel::Extent& e) {
          return e.from <= e.to && w.dot(at.axis) + (at.axis[k] > 0.0 ? e.to : e.from) * at.axis[k] > highest;
        };
        if (!beats(stockSpan) && !beats(partSpan)) continue;
        // The ray o + t·e_k within the holder's infinite cylinder about the axis.
        Eigen::Vector3d d = Eigen::Vector3d::Zero();
        d[k] = 1.0;
        const Eigen::Vector3d wp = w - w.dot(at.axis) * at.axis, dp = d - d.dot(at.axis) * at.axis;
        const double A = dp.squaredNorm(), B = 2.0 * wp.dot(dp), C = wp.squaredNorm() - radius * radius;
        double t0 = -std::numeric_limits<double>::infinity(), t1 = -t0;
        if (A > 1e-12) {
          const double disc = B * B - 4.0 * A * C;
          if (disc < 0.0) continue;
          t0 = (-B - std::sqrt(disc)) / (2.0 * A), t1 = (-B + std::sqrt(disc)) / (2.0 * A);
        } else if (C > 0.0) {
          continue;
        }
        for (const TriDexel* model : {&material_, &part_}) {
          const TriDexel::Extent e = model == &material_ ? stockSpan : partSpan;
          const double a = std::max<double>(e.from, t0), b = std::min<double>(e.to, t1);
          if (b <= a || std::max(w.dot(at.axis) + a * at.axis[k], w.dot(at.axis) + b * at.axis[k]) <= highest) continue;
          for (const Interval& s : model->at(k, i, j)) {
            const double a = std::max(s.from, t0), b = std::min(s.to, t1);
            if (b <= a) continue;
            highest = std::max(highest, std::max(w.dot(at.axis) + a * at.axis[k], w.dot(at.axis) + b * at.axis[k]));
          }
        }
      }
    }
    return highest;
  }

  // The stock left on the samples (read chunk by chunk on the threads), and its statistics (in order).
  void thicknessOf(const std::vector<std::vector<Sample>>& samples, RemovalResult& r) const {
    std::vector<size_t> offset(1, 0);
    for (const std::vector<Sample>& chunk : samples) offset.push_back(offset.back() + chunk.size());
    r.surfacePoints.resize(offset.back()), r.thickness.resize(offset.back()), r.weight.resize(offset.back());
    parallelChunks(static_cast<long>(samples.size()), threads_, 1, [&](long from, long to) {
      for (long c = from; c < to; ++c)
        for (size_t i = 0; i < samples[c].size(); ++i) {
          const Sample& s = samples[c][i];
          r.surfacePoints[offset[c] + i] = s.point, r.thickness[offset[c] + i] = stockAt(material_, s);
          r.weight[offset[c] + i] = s.weight;
        }
    });
    double total = 0.0, sum = 0.0, squares = 0.0;
    for (size_t i = 0; i < r.thickness.size(); ++i) {
      const double t = r.thickness[i], w = r.weight[i];
      total += w, sum += w * t, squares += w * t * t;
      r.thicknessMax = std::max(r.thicknessMax, t);
    }
    if (total > 0.0) {
      r.thicknessMean = sum / total;
      r.thicknessStd = std::sqrt(std::max(0.0, squares / total - r.thicknessMean * r.thicknessMean));
    }
  }

  const RemovalSettings& settings_;
  Shape shape_;  // the cutter of the run going on
  Cutter cutter_;
  int threads_ = 1;
  int lanes_ = 1;  // of rows each, taken by the threads in turn
  geometry::TriangleMesh stockMesh_, partMesh_;
  Eigen::AlignedBox3d stockBox_;
  TriDexel material_, part_;
  TriDexel uncut_;  // the part not yet entered by the tool: a gouge is counted once
};

}  // namespace

std::vector<ToolMove> feedThroughStock(const std::vector<ToolMove>& moves, const std::vector<RapidFault>& faults,
                                       double margin) {
  if (!(margin >= 0.0 && margin <= 1000.0))
    throw InputError("rapids in stock: margin " + number(margin) + " mm is outside [0, 1000] mm (default 1)");
  std::vector<ToolMove> out;
  out.reserve(moves.size() + faults.size());
  size_t next = 0;
  for (size_t i = 0; i < moves.size(); ++i) {
    if (next < faults.size() && faults[next].move == static_cast<int>(i)) {
      const RapidFault& fault = faults[next++];
      if (i == 0 || moves[i].kind != MoveKind::Rapid || !(fault.along >= 0.0 && fault.along <= 1.0))
        throw InputError("rapids in stock: fault of move " + std::to_string(fault.move) +
                         " is not a rapid of these moves (simulate these moves)");
      const ToolMove& a = moves[i - 1];
      const double length = (moves[i].tip - a.tip).norm();
      const double split = length > 0.0 ? std::max(0.0, fault.along - margin / length) : 0.0;
      if (split > 0.0) {
        ToolMove air = moves[i];
        air.tip = a.tip + split * (moves[i].tip - a.tip);
        air.axis = ((1.0 - split) * a.axis.normalized() + split * moves[i].axis.normalized()).normalized();
        out.push_back(air);
      }
      ToolMove into = moves[i];
      into.kind = MoveKind::Plunge;
      out.push_back(into);
      continue;
    }
    out.push_back(moves[i]);
  }
  if (next != faults.size())
    throw InputError("rapids in stock: fault of move " + std::to_string(faults[next].move) +
                     " is not in these moves, or the faults are not in the moves' order");
  return out;
}

RapidsMended keepRapidsOutOfStock(const std::vector<ToolMove>& moves, const Cutter& cutter, const TopoDS_Shape& stock,
                                  const TopoDS_Shape& part, const RemovalSettings& settings, double margin,
                                  const std::vector<ToolRun>& before) {
  RemovalSettings quick = settings;
  quick.stockMeshStride = 0;
  quick.restSpacing = 0.0;
  std::vector<ToolRun> runs = before;
  runs.push_back({moves, cutter});
  RemovalResult r = simulateRemoval(runs, stock, part, quick);
  int offset = 0;
  for (const ToolRun& run : before) offset += static_cast<int>(run.moves.size());
  std::vector<RapidFault> own;  // the faults of these moves, numbered in them
  for (RapidFault f : r.rapidFaults)
    if (f.move >= offset) f.move -= offset, own.push_back(f);
  r.rapidFaults = std::move(own);
  // The first position that cut may be a sampling step past where the tool met the stock; and the stock's
  // skin is known to a ray spacing.
  const double skin = sampleStep(cutter, settings.resolution) + std::sqrt(2.0) * settings.resolution;
  return {feedThroughStock(moves, r.rapidFaults, margin + skin), r.rapidFaults};
}

RemovalResult simulateRemoval(const std::vector<ToolMove>& moves, const Cutter& cutter, const TopoDS_Shape& stock,
                              const TopoDS_Shape& part, const RemovalSettings& settings) {
  return simulateRemoval(std::vector<ToolRun>{{moves, cutter}}, stock, part, settings);
}

RemovalResult simulateRemoval(const std::vector<ToolRun>& runs, const TopoDS_Shape& stock, const TopoDS_Shape& part,
                              const RemovalSettings& settings) {
  for (const ToolRun& run : runs) checkCutter(run.cutter);
  if (!(settings.resolution >= 0.005 && settings.resolution <= 50.0))  // before anything is meshed at it
    throw InputError("material-removal resolution " + number(settings.resolution) +
                     " mm is outside [0.005, 50] mm (default 0.2)");
  if (!(settings.chipSection > 0.0 && settings.chipSection < 1e3))
    throw InputError("material removal: chip section " + number(settings.chipSection) + " mm² must be in ]0, 1000[ (default 0.1)");
  if (!(settings.stickOutSpacing >= 0.1 && settings.stickOutSpacing <= 1e4))
    throw InputError("material removal: stick-out spacing " + number(settings.stickOutSpacing) +
                     " mm is outside [0.1, 10000] mm (default 5)");
  if (!(settings.allowance >= 0.0 && settings.allowance <= 100.0))
    throw InputError("material removal: allowance " + number(settings.allowance) + " mm is outside [0, 100] mm (default 0.5)");
  if (settings.stockMeshStride < 0 || settings.stockMeshStride > 100)
    throw InputError("material removal: stock mesh stride " + std::to_string(settings.stockMeshStride) +
                     " is outside [0, 100] rays (0: no mesh)");
  checkThreads(settings.threads, "material removal");
  if (stock.IsNull()) throw InputError("material removal: no stock");
  if (settings.restSpacing != 0.0 && !(settings.restSpacing >= settings.resolution && settings.restSpacing <= 20.0))
    throw InputError("material removal: rest spacing " + number(settings.restSpacing) + " mm is outside [" +
                     number(settings.resolution) + " (the resolution), 20] mm, or 0 for no rest stock");
  for (const ToolRun& run : runs)
    for (const ToolMove& m : run.moves)
      if (!m.tip.allFinite() || !m.axis.allFinite() || !(m.axis.norm() > 1e-9))
        throw InputError("material removal: a move has a tip or an axis that is not a finite point and direction");
  return Simulation(stock, part, settings).run(runs);
}

}  // namespace hsm::roughing
