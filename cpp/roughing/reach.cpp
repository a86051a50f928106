// What a roughing path leaves, split by cause (reach.hpp): a drop-cutter of the part's heights along the
// slicing's columns, the floor the tool reaches from it, and the solid's material integrated column by column.
#include "roughing/reach.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/dexel.hpp"
#include "roughing/flat.hpp"
#include "roughing/grown_cutter.hpp"
#include "roughing/projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {

constexpr long kMaxSamples = 100'000'000;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The columns of a level laid flat: cells of `size` flat mm from (x0, y0).
struct Grid {
  double x0 = 0.0, y0 = 0.0, size = 1.0;
  int nx = 0, ny = 0;
  long cells() const { return static_cast<long>(nx) * ny; }
  cl::IntPoint centre(int i, int j) const {
    return {static_cast<cl::cInt>(std::llround((x0 + (i + 0.5) * size) * kScale)),
            static_cast<cl::cInt>(std::llround((y0 + (j + 0.5) * size) * kScale))};
  }
  long cellOf(const cl::IntPoint& q) const {
    const int i = static_cast<int>(std::floor((double(q.X) / kScale - x0) / size));
    const int j = static_cast<int>(std::floor((double(q.Y) / kScale - y0) / size));
    return i < 0 || j < 0 || i >= nx || j >= ny ? -1 : static_cast<long>(j) * nx + i;
  }
};

// True mm per flat mm along x and y at column q, height h: from the projection's own points.
Eigen::Vector2d scalesOf(const Projection& projection, const cl::IntPoint& q, double h, double step) {
  const cl::cInt d = static_cast<cl::cInt>(std::llround(step * kScale));
  const Eigen::Vector3d p = projection.point(q, h);
  return {(projection.point({q.X + d, q.Y}, h) - p).norm() / step, (projection.point({q.X, q.Y + d}, h) - p).norm() / step};
}

// A value per cell, at a point of the plane (the cell's centre, or where the value was found in it).
struct Field {
  std::vector<double> value, height;  // the value; the height the plane's scales are taken at
  std::vector<Eigen::Vector2d> where; // flat mm
};

// For every cell c with a value (finite, or −∞), every cell q whose centre lies within `reach` true mm of where
// c's value is (an ellipse over the scales there) gets join(out[q], value + profile(distance)).
template <class Profile, class Join>
void spread(const Grid& grid, const Projection& projection, const Field& field, double reach, Profile&& profile,
            Join&& join, std::vector<double>& out) {
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const long c = static_cast<long>(j) * grid.nx + i;
      if (std::isnan(field.value[c]) || field.value[c] == kInfinity) continue;
      const Eigen::Vector2d s = scalesOf(projection, grid.centre(i, j), field.height[c], grid.size).cwiseMax(1e-3);
      const int rx = static_cast<int>(std::ceil(reach / (s.x() * grid.size))) + 1;
      const int ry = static_cast<int>(std::ceil(reach / (s.y() * grid.size))) + 1;
      const Eigen::Vector2d at = field.where[c];
      for (int dj = -ry; dj <= ry; ++dj)
        for (int di = -rx; di <= rx; ++di) {
          const int qi = i + di, qj = j + dj;
          if (qi < 0 || qj < 0 || qi >= grid.nx || qj >= grid.ny) continue;
          const double dx = grid.x0 + (qi + 0.5) * grid.size - at.x(), dy = grid.y0 + (qj + 0.5) * grid.size - at.y();
          const double rho = std::hypot(s.x() * dx, s.y() * dy);
          if (rho > reach) continue;
          double& o = out[static_cast<long>(qj) * grid.nx + qi];
          o = join(o, field.value[c] + profile(rho));
        }
    }
}

class Splitter {
public:
  Splitter(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part, const Cutter& cutter,
           double allowance, double resolution, int threads)
      : projection_(projectionOf(partition, solid)), cutter_(cutter), allowance_(allowance), g_(resolution),
        threads_(threads), solidMesh_(geometry::meshFacesAfresh(solid.solid, std::min(0.05, resolution / 4))),
        partMesh_(geometry::meshFacesAfresh(part, std::min(0.05, resolution / 4))) {
    low_ = kInfinity, high_ = -kInfinity;
    for (const Eigen::Vector3d& p : solidMesh_.vertices) {
      const double h = projection_->height(p);
      if (std::isfinite(h)) low_ = std::min(low_, h), high_ = std::max(high_, h);
    }
    if (!(high_ > low_)) throw ComputationError("the solid has no extent along the slicing's axes");
    projection_->setLevel(0.5 * (low_ + high_), solidMesh_);
    region_ = projectedUnion(solidMesh_, *projection_, -kInfinity);
    const Window box = windowAround(region_, 0.0);
    double least = kInfinity;
    for (const Eigen::Vector3d& p : solidMesh_.vertices)
      if (std::isfinite(projection_->height(p)))
        least = std::min(least, scalesOf(*projection_, projection_->plane(p), projection_->height(p), g_).minCoeff());
    // Beyond the region only the part next to it matters (its walls bound the region): the margin at a scale
    // of at least a half keeps the grid small where the plane is shrunk (the impeller's inlet, 0.2).
    const double margin = (cutter.radius() + allowance + 1.0) / std::clamp(least, 0.5, 1.0);
    grid_.size = g_;
    grid_.x0 = box.x0 / kScale - margin, grid_.y0 = box.y0 / kScale - margin;
    grid_.nx = static_cast<int>(std::ceil((box.x1 - box.x0) / kScale / g_ + 2 * margin / g_));
    grid_.ny = static_cast<int>(std::ceil((box.y1 - box.y0) / kScale / g_ + 2 * margin / g_));
    const long samples = grid_.cells() * static_cast<long>(std::ceil((high_ - low_) / g_));
    if (samples > kMaxSamples)
      throw InputError("split of what is left: resolution " + number(g_) + " mm needs " + std::to_string(samples) +
                       " samples, more than " + std::to_string(kMaxSamples) + ": use at least " +
                       number(g_ * std::cbrt(double(samples) / kMaxSamples)) + " mm");
  }

  LeftSplit run(const std::vector<ToolMove>& moves) {
    LeftSplit split;
    split.resolution = g_;
    const std::vector<double> levels = levelsOf(moves);
    split.levels = static_cast<int>(levels.size());
    const Field top = partTop();
    // The envelope: the lowest tip height per column at which the grown cutter touches no part point.
    Field envelope{std::vector<double>(grid_.cells(), -kInfinity), {}, {}};
    spread(grid_, *projection_, top, cutter_.radius() + allowance_, [&](double rho) { return -GrownCutter::lowestAt(cutter_, allowance_, rho); },
           [](double a, double b) { return std::max(a, b); }, envelope.value);
    // The floors: from the envelope, and from the lowest level at or above it.
    envelope.height.resize(grid_.cells());
    envelope.where.resize(grid_.cells());
    Field atLevel = envelope;
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        const long c = static_cast<long>(j) * grid_.nx + i;
        const auto above = std::lower_bound(levels.begin(), levels.end(), envelope.value[c] - 1e-6);
        atLevel.value[c] = above == levels.end() ? kInfinity : *above;
        envelope.height[c] = atLevel.height[c] = std::isfinite(envelope.value[c]) ? envelope.value[c] : 0.5 * (low_ + high_);
        envelope.where[c] = atLevel.where[c] = {grid_.x0 + (i + 0.5) * grid_.size, grid_.y0 + (j + 0.5) * grid_.size};
      }
    const auto tool = [&](double rho) { return GrownCutter::lowestAt(cutter_, 0.0, rho); };
    const auto least = [](double a, double b) { return std::min(a, b); };
    std::vector<double> floor(grid_.cells(), kInfinity), floorOfLevels(grid_.cells(), kInfinity);
    spread(grid_, *projection_, envelope, cutter_.radius(), tool, least, floor);
    spread(grid_, *projection_, atLevel, cutter_.radius(), tool, least, floorOfLevels);
    integrate(floor, floorOfLevels, split);
    return split;
  }

private:
  std::vector<double> levelsOf(const std::vector<ToolMove>& moves) const {
    std::vector<double> levels;
    for (const ToolMove& m : moves)
      if (m.kind == MoveKind::Cut) {
        const double h = projection_->height(m.tip);
        if (std::isfinite(h)) levels.push_back(std::round(h * 1e3) / 1e3);
      }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
  }

  // The highest point of the part's surface over each column (NaN where none) and where it is, from points of
  // its triangles half a cell apart at the plane's least scale.
  Field partTop() const {
    Field top{std::vector<double>(grid_.cells(), std::numeric_limits<double>::quiet_NaN()), {},
              std::vector<Eigen::Vector2d>(grid_.cells())};
    for (const Eigen::Vector3i& t : partMesh_.triangles) {
      const Eigen::Vector3d p[3] = {partMesh_.vertices[t[0]], partMesh_.vertices[t[1]], partMesh_.vertices[t[2]]};
      if (projection_->skip(p)) continue;
      if (grid_.cellOf(projection_->plane(p[0])) < 0 && grid_.cellOf(projection_->plane(p[1])) < 0 &&
          grid_.cellOf(projection_->plane(p[2])) < 0)
        continue;
      const Eigen::Vector2d s =
          projection_->scalesAt(p[0]).cwiseMin(projection_->scalesAt(p[1])).cwiseMin(projection_->scalesAt(p[2]));
      const double spacing = 0.5 * g_ * std::clamp(s.minCoeff(), 0.05, 1.0);
      const double edge = std::max({(p[1] - p[0]).norm(), (p[2] - p[1]).norm(), (p[0] - p[2]).norm()});
      const int m = std::max(1, static_cast<int>(std::ceil(edge / spacing)));
      for (int a = 0; a <= m; ++a)
        for (int b = 0; a + b <= m; ++b) {
          const Eigen::Vector3d q = p[0] + (p[1] - p[0]) * (double(a) / m) + (p[2] - p[0]) * (double(b) / m);
          const double h = projection_->height(q);
          const cl::IntPoint flat = projection_->plane(q);
          const long c = grid_.cellOf(flat);
          if (c < 0 || !std::isfinite(h) || h <= top.value[c]) continue;
          top.value[c] = h;
          top.where[c] = {double(flat.X) / kScale, double(flat.Y) / kScale};
        }
    }
    top.height = top.value;
    return top;
  }

  // The solid's material, column by column over the region's box, on its tri-dexel model.
  void integrate(const std::vector<double>& floor, const std::vector<double>& floorOfLevels, LeftSplit& split) const {
    TriDexel material(solidMesh_.bounds(), g_, kMaxSamples);
    material.fill(solidMesh_);
    const int heights = static_cast<int>(std::ceil((high_ - low_) / g_));
    const int workers = threadCount(threads_);
    std::vector<Eigen::Vector3d> sums(workers, Eigen::Vector3d::Zero());  // volume, unreachable, between
    std::atomic<int> nextWorker{0};
    parallelSlices(grid_.ny, workers, 1, [&](long from, long to) {
      Eigen::Vector3d& sum = sums[nextWorker++];
      for (long j = from; j < to; ++j)
        for (int i = 0; i < grid_.nx; ++i) {
          const long c = j * grid_.nx + i;
          const cl::IntPoint q = grid_.centre(i, static_cast<int>(j));
          for (int k = 0; k < heights; ++k) {
            const double h = low_ + (k + 0.5) * g_;
            if (!material.inside(projection_->point(q, h))) continue;
            const Eigen::Vector2d s = scalesOf(*projection_, q, h, 0.5 * g_);
            const double volume = s.x() * s.y() * g_ * g_ * g_;
            sum[0] += volume;
            if (h < floor[c]) sum[1] += volume;
            else if (h < floorOfLevels[c]) sum[2] += volume;
          }
        }
    });
    for (const Eigen::Vector3d& s : sums) split.volume += s[0], split.unreachable += s[1], split.betweenLevels += s[2];
  }

  std::unique_ptr<Projection> projection_;
  Cutter cutter_;
  double allowance_, g_;
  int threads_;
  geometry::TriangleMesh solidMesh_, partMesh_;
  double low_ = 0.0, high_ = 0.0;
  cl::Paths region_;
  Grid grid_;
};

}  // namespace

LeftSplit splitWhatIsLeft(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part,
                          const Cutter& cutter, double allowance, const std::vector<ToolMove>& moves, double resolution,
                          int threads) {
  checkCutter(cutter);
  if (!(resolution >= 0.1 && resolution <= 5.0))
    throw InputError("split of what is left: resolution " + number(resolution) + " mm is outside [0.1, 5] mm (default 0.25)");
  if (!(allowance >= 0.0 && allowance <= 100.0))
    throw InputError("split of what is left: allowance " + number(allowance) + " mm is outside [0, 100] mm");
  checkThreads(threads, "split of what is left");
  if (partition.subVolumes.empty()) throw InputError("split of what is left: the partition has no sub-volumes");
  return Splitter(partition, solid, part, cutter, allowance, resolution, threads).run(moves);
}

}  // namespace hsm::roughing
