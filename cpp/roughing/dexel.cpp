#include "roughing/dexel.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace hsm::roughing {

double subtract(Intervals& intervals, double from, double to) {
  if (!(to > from)) return 0.0;
  // In place (a removal simulation calls this for every ray a cutter crosses): the intervals [a, b) that
  // overlap ]from, to[ give way to what is left of the first and of the last.
  size_t a = 0;
  while (a < intervals.size() && intervals[a].to <= from) ++a;
  size_t b = a;
  double taken = 0.0;
  for (; b < intervals.size() && intervals[b].from < to; ++b)
    taken += std::min(intervals[b].to, to) - std::max(intervals[b].from, from);
  if (b == a) return 0.0;
  Interval left{intervals[a].from, from}, right{to, intervals[b - 1].to};
  const size_t kept = (left.from < left.to ? 1 : 0) + (right.from < right.to ? 1 : 0);
  if (kept > b - a) intervals.insert(intervals.begin() + static_cast<long>(a), Interval{});  // one split in two
  else intervals.erase(intervals.begin() + static_cast<long>(a + kept), intervals.begin() + static_cast<long>(b));
  size_t at = a;
  if (left.from < left.to) intervals[at++] = left;
  if (right.from < right.to) intervals[at] = right;
  return taken;
}

double overlap(const Intervals& intervals, double from, double to) {
  double total = 0.0;
  for (const Interval& s : intervals)
    if (s.to > from && s.from < to) total += std::min(s.to, to) - std::max(s.from, from);
  return total;
}

TriDexel::TriDexel(const Eigen::AlignedBox3d& box, double resolution, long maxRays) : h_(resolution) {
  if (!(resolution >= 0.005 && resolution <= 50.0))
    throw InputError("material-removal resolution " + number(resolution) + " mm is outside [0.005, 50] mm (default 0.2)");
  if (box.isEmpty()) throw InputError("material-removal: the stock is empty");
  low_ = box.min() - Eigen::Vector3d::Constant(h_);
  const Eigen::Vector3d size = box.sizes() + Eigen::Vector3d::Constant(2.0 * h_);
  long total = 0;
  double area = 0.0;
  for (int k = 0; k < 3; ++k) {
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    n_[k][0] = std::max(1, static_cast<int>(std::ceil(size[u] / h_)));
    n_[k][1] = std::max(1, static_cast<int>(std::ceil(size[v] / h_)));
    total += static_cast<long>(n_[k][0]) * n_[k][1];
    area += size[u] * size[v];
    // Irrational fractions of a spacing: no ray through a grid-aligned edge or vertex of a mesh.
    jitter_[k][0] = h_ * (0.5 + 1.2345678e-5 * (k + 1));
    jitter_[k][1] = h_ * (0.5 + 2.7182818e-5 * (k + 1));
  }
  if (total > maxRays)
    throw InputError("material removal at " + number(resolution) + " mm needs " + std::to_string(total) +
                     " rays (more than " + std::to_string(maxRays) + "): use a resolution of at least " +
                     number(std::sqrt(area / double(maxRays))) + " mm");
  for (int k = 0; k < 3; ++k) {
    rays_[k].resize(static_cast<size_t>(n_[k][0]) * n_[k][1]);
    extents_[k].assign(rays_[k].size(), Extent{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()});
  }
}

namespace {
// The float nearest x at or below it (a cast rounds to the nearest, which may be above).
float floatBelow(double x) {
  float f = static_cast<float>(x);
  if (f > x) {  // the float next below f, by its bits (libm's nextafterf is a call for every ray cut)
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    if (f > 0.0f) --bits;
    else if (f < 0.0f) ++bits;
    else bits = 0x80000001u;  // the least negative float below 0
    std::memcpy(&f, &bits, sizeof f);
  }
  return f;
}
}  // namespace

void TriDexel::keepExtent(int k, size_t r) {
  const Intervals& ray = rays_[k][r];
  Extent& e = extents_[k][r];
  if (ray.empty()) {
    e = {std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
    return;
  }
  e.from = floatBelow(ray.front().from);
  e.to = -floatBelow(-ray.back().to);
}

double TriDexel::remove(int k, int i, int j, double from, double to) {
  const size_t r = index(k, i, j);
  const double taken = roughing::subtract(rays_[k][r], from, to);
  if (taken > 0.0) keepExtent(k, r);
  return taken;
}

long TriDexel::rays() const {
  return static_cast<long>(rays_[0].size() + rays_[1].size() + rays_[2].size());
}

void TriDexel::rangeOf(int k, const Eigen::AlignedBox3d& box, int& i0, int& i1, int& j0, int& j1) const {
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  auto first = [&](double x, int axis, int a) {
    return std::max(0, static_cast<int>(std::ceil((x - low_[axis] - jitter_[k][a]) / h_)));
  };
  auto last = [&](double x, int axis, int a, int n) {
    return std::min(n - 1, static_cast<int>(std::floor((x - low_[axis] - jitter_[k][a]) / h_)));
  };
  i0 = first(box.min()[u], u, 0), i1 = last(box.max()[u], u, 0, n_[k][0]);
  j0 = first(box.min()[v], v, 1), j1 = last(box.max()[v], v, 1, n_[k][1]);
}

bool TriDexel::inside(const Eigen::Vector3d& p) const {
  const int i = static_cast<int>(std::lround((p.x() - low_.x() - jitter_[2][0]) / h_));
  const int j = static_cast<int>(std::lround((p.y() - low_.y() - jitter_[2][1]) / h_));
  if (i < 0 || j < 0 || i >= n_[2][0] || j >= n_[2][1]) return false;
  for (const Interval& s : at(2, i, j))
    if (p.z() >= s.from && p.z() < s.to) return true;
  return false;
}

void TriDexel::fill(const geometry::TriangleMesh& mesh, int threads) {
  // Bands of rows filled side by side; each ray sees the triangles in the mesh's order, as on one thread.
  struct Band {
    int k, from, to;
  };
  std::vector<Band> bands;
  const int perDirection = 4 * threadCount(threads);
  for (int k = 0; k < 3; ++k) {
    const int rows = n_[k][1], size = std::max(16, (rows + perDirection - 1) / perDirection);
    for (int from = 0; from < rows; from += size) bands.push_back({k, from, std::min(rows, from + size)});
  }
  parallelChunks(static_cast<long>(bands.size()), threads, 1, [&](long first, long last) {
    for (long b = first; b < last; ++b) fillRows(mesh, bands[b].k, bands[b].from, bands[b].to);
  });
}

void TriDexel::fillRows(const geometry::TriangleMesh& mesh, int k, int from, int to) {
  const int u = (k + 1) % 3, v = (k + 2) % 3;
  const size_t first = index(k, 0, from);
  std::vector<std::vector<double>> crossings(index(k, 0, to) - first);
  const double low = origin(k, 0, from)[v] - h_, high = origin(k, 0, to - 1)[v] + h_;  // the band's rows, and a spacing
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    if (std::max({a[v], b[v], c[v]}) < low || std::min({a[v], b[v], c[v]}) > high) continue;  // another band's
    // The triangle seen along k: a ray crosses it where its (u, v) is inside (barycentric, half-open edges).
    const double area = (b[u] - a[u]) * (c[v] - a[v]) - (c[u] - a[u]) * (b[v] - a[v]);
    if (area == 0.0) continue;
    Eigen::AlignedBox3d box(a);
    box.extend(b), box.extend(c);
    int i0, i1, j0, j1;
    rangeOf(k, box, i0, i1, j0, j1);
    for (int j = std::max(j0, from); j <= std::min(j1, to - 1); ++j)
      for (int i = i0; i <= i1; ++i) {
        const Eigen::Vector3d o = origin(k, i, j);
        const double wa = ((b[u] - o[u]) * (c[v] - o[v]) - (c[u] - o[u]) * (b[v] - o[v])) / area;
        const double wb = ((c[u] - o[u]) * (a[v] - o[v]) - (a[u] - o[u]) * (c[v] - o[v])) / area;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        crossings[index(k, i, j) - first].push_back(wa * a[k] + wb * b[k] + wc * c[k]);
      }
  }
  for (size_t r = 0; r < crossings.size(); ++r) {
    std::vector<double>& x = crossings[r];
    std::sort(x.begin(), x.end());
    Intervals& out = rays_[k][first + r];
    out.clear();
    for (size_t m = 0; m + 1 < x.size(); m += 2)
      if (x[m + 1] > x[m]) out.push_back({x[m], x[m + 1]});
    keepExtent(k, first + r);
  }
}

void TriDexel::subtract(const TriDexel& other, int threads) {
  for (int k = 0; k < 3; ++k)
    parallelChunks(static_cast<long>(rays_[k].size()), threads, 1 << 14, [&](long first, long last) {
      for (size_t r = static_cast<size_t>(first); r < static_cast<size_t>(last); ++r) {
        for (const Interval& s : other.rays_[k][r]) roughing::subtract(rays_[k][r], s.from, s.to);
        keepExtent(k, r);
      }
    });
}

void TriDexel::assign(const TriDexel& other, int threads) {
  for (int k = 0; k < 3; ++k) {
    extents_[k] = other.extents_[k];
    parallelChunks(static_cast<long>(rays_[k].size()), threads, 1 << 14, [&](long first, long last) {
      for (long r = first; r < last; ++r) rays_[k][r] = other.rays_[k][r];
    });
  }
}

geometry::TriangleMesh TriDexel::blocks(int stride) const {
  geometry::TriangleMesh mesh;
  const int nx = (n_[2][0] + stride - 1) / stride, ny = (n_[2][1] + stride - 1) / stride;
  const double size = stride * h_;
  auto column = [&](int a, int b) -> const Intervals* {
    if (a < 0 || b < 0 || a >= nx || b >= ny) return nullptr;
    return &at(2, std::min(a * stride + stride / 2, n_[2][0] - 1), std::min(b * stride + stride / 2, n_[2][1] - 1));
  };
  // A quad of four corners (counter-clockwise seen from outside) as two triangles.
  auto quad = [&](const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
    const int base = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {p0, p1, p2, p3});
    mesh.triangles.emplace_back(base, base + 1, base + 2);
    mesh.triangles.emplace_back(base, base + 2, base + 3);
  };
  // Z rays run along Z with u = X, v = Y: column (a, b) covers [x0, x0 + size] × [y0, y0 + size].
  const double x00 = low_.x(), y00 = low_.y();
  for (int b = 0; b < ny; ++b)
    for (int a = 0; a < nx; ++a) {
      const Intervals& here = *column(a, b);
      if (here.empty()) continue;
      const double x0 = x00 + a * size, x1 = x0 + size, y0 = y00 + b * size, y1 = y0 + size;
      for (const Interval& s : here) {
        quad({x0, y0, s.to}, {x1, y0, s.to}, {x1, y1, s.to}, {x0, y1, s.to});
        quad({x0, y0, s.from}, {x0, y1, s.from}, {x1, y1, s.from}, {x1, y0, s.from});
      }
      // Sides: where this column has material and its neighbour has none.
      const int da[4] = {1, -1, 0, 0}, db[4] = {0, 0, 1, -1};
      for (int side = 0; side < 4; ++side) {
        Intervals open = here;
        if (const Intervals* next = column(a + da[side], b + db[side]))
          for (const Interval& s : *next) roughing::subtract(open, s.from, s.to);
        for (const Interval& s : open) {
          const double z0 = s.from, z1 = s.to;
          if (side == 0) quad({x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1});
          if (side == 1) quad({x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0});
          if (side == 2) quad({x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0});
          if (side == 3) quad({x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1});
        }
      }
    }
  return mesh;
}

double TriDexel::volume() const {
  double length = 0.0;
  for (const Intervals& ray : rays_[2])
    for (const Interval& s : ray) length += s.to - s.from;
  return length * h_ * h_;
}

}  // namespace hsm::roughing
