// Drop-cutter throughput against OpenCAMLib 2022.12's BatchDropCutter on the same raster (DESIGN.md):
// Ø4 mm ball on shared/data/wavy_surface.stl (19k triangles), 0.4 mm stepover × 0.05 mm sampling, 423k
// points; OpenCAMLib about 12,000 points/s on one core and 24,000 on two. Run: build/bin/bench_dropcutter
#include "geometry/plan_grid.hpp"
#include "toolpath/dropcutter.hpp"

#include <BVH_BoxSet.hxx>
#include <BVH_LinearBuilder.hxx>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace hsm::geometry;
using namespace hsm::toolpath;

namespace {
double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The spatial search alone, hand-written grid against OCCT's BVH (keep the grid only if it is
// faster): the triangles whose plan box grown by the radius may hold the ball at each raster point.
void compareSpatialSearch(const TriangleMesh& mesh, const hsm::geometry::PointArray& raster, double radius) {
  std::vector<Eigen::AlignedBox2d> boxes;
  Eigen::AlignedBox2d plan;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    Eigen::AlignedBox2d box;
    for (int k = 0; k < 3; ++k) box.extend(mesh.vertices[t[k]].head<2>());
    boxes.push_back(box);
    plan.extend(box);
  }
  auto start = std::chrono::steady_clock::now();
  hsm::geometry::PlanGrid<std::vector<int>> grid(plan, radius, radius, "the mesh");
  for (size_t i = 0; i < boxes.size(); ++i)
    grid.forBox(boxes[i].min().x(), boxes[i].min().y(), boxes[i].max().x(), boxes[i].max().y(),
                [&](std::vector<int>& cell) { cell.push_back(static_cast<int>(i)); });
  const double gridBuild = seconds(start);
  start = std::chrono::steady_clock::now();
  long gridFound = 0;
  for (Eigen::Index p = 0; p < raster.rows(); ++p) {
    const double x = raster(p, 0), y = raster(p, 1);
    if (const auto* cell = grid.at(x, y))
      for (int i : *cell) {  // the same exact candidates as the tree's: the cell lists a superset
        const Eigen::AlignedBox2d& box = boxes[static_cast<size_t>(i)];
        if (x >= box.min().x() - radius && x <= box.max().x() + radius && y >= box.min().y() - radius &&
            y <= box.max().y() + radius)
          ++gridFound;
      }
  }
  const double gridQuery = seconds(start);

  start = std::chrono::steady_clock::now();
  BVH_BoxSet<Standard_Real, 2, int> set(new BVH_LinearBuilder<Standard_Real, 2>());
  for (size_t i = 0; i < boxes.size(); ++i)
    set.Add(static_cast<int>(i), BVH_Box<Standard_Real, 2>(BVH_Vec2d(boxes[i].min().x() - radius, boxes[i].min().y() - radius),
                                                          BVH_Vec2d(boxes[i].max().x() + radius, boxes[i].max().y() + radius)));
  set.Build();
  const opencascade::handle<BVH_Tree<Standard_Real, 2>>& tree = set.BVH();
  const double bvhBuild = seconds(start);
  start = std::chrono::steady_clock::now();
  long bvhFound = 0;
  std::vector<int> stack;
  for (Eigen::Index p = 0; p < raster.rows(); ++p) {
    const double x = raster(p, 0), y = raster(p, 1);
    stack.assign(1, 0);
    while (!stack.empty()) {
      const int node = stack.back();
      stack.pop_back();
      const BVH_Vec2d& lo = tree->MinPoint(node);
      const BVH_Vec2d& hi = tree->MaxPoint(node);
      if (x < lo.x() || x > hi.x() || y < lo.y() || y > hi.y()) continue;
      if (tree->IsOuter(node)) {
        for (int i = tree->BegPrimitive(node); i <= tree->EndPrimitive(node); ++i) {
          const BVH_Box<Standard_Real, 2> box = set.Box(i);
          if (x >= box.CornerMin().x() && x <= box.CornerMax().x() && y >= box.CornerMin().y() && y <= box.CornerMax().y())
            ++bvhFound;
        }
      } else {
        stack.push_back(tree->Child<0>(node));
        stack.push_back(tree->Child<1>(node));
      }
    }
  }
  const double bvhQuery = seconds(start);
  std::printf("spatial search, %ld queries: grid %.3f s (+%.3f s build, %.1f candidates/query), OCCT BVH %.3f s "
              "(+%.3f s build, %.1f/query): grid %.1fx faster\n",
              static_cast<long>(raster.rows()), gridQuery, gridBuild, double(gridFound) / raster.rows(), bvhQuery,
              bvhBuild, double(bvhFound) / raster.rows(), bvhQuery / gridQuery);
}
}  // namespace

int main(int argc, char** argv) {
  const char* env = std::getenv("HSM_SHARED_DATA");
  const std::string folder = argc > 1 ? argv[1] : env ? env : HSM_SHARED_DATA_DIR;
  const TriangleMesh mesh = readStl(folder + "/wavy_surface.stl");
  const Eigen::AlignedBox3d box = mesh.bounds();
  hsm::geometry::PointArray raster;
  std::vector<Eigen::RowVector3d> rows;
  for (double y = box.min().y(); y <= box.max().y() + 1e-9; y += 0.4)
    for (double x = box.min().x(); x <= box.max().x() + 1e-9; x += 0.05) rows.emplace_back(x, y, 0.0);
  raster.resize(static_cast<Eigen::Index>(rows.size()), 3);
  for (size_t i = 0; i < rows.size(); ++i) raster.row(static_cast<Eigen::Index>(i)) = rows[i];

  const auto build = std::chrono::steady_clock::now();
  const BallDropCutter cutter(mesh, 2.0);
  const double buildTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - build).count();
  std::printf("%zu triangles, %.0f x %.0f mm, %ld cutter-location points; index built in %.3f s\n",
              mesh.triangles.size(), box.sizes().x(), box.sizes().y(), static_cast<long>(raster.rows()), buildTime);
  // Why equal halves scaled 1.3-1.7x: the cost of a point follows the mesh's density under it, so
  // the two contiguous halves of the raster cost unequally and one thread waited for the other. Chunks taken
  // in turn (parallelChunks) balance it; the halves' times on one thread show the imbalance they had.
  const Eigen::Index half = raster.rows() / 2;
  double halves[2];
  for (int k = 0; k < 2; ++k) {
    hsm::geometry::PointArray part = raster.middleRows(k * half, k == 0 ? half : raster.rows() - half);
    const auto start = std::chrono::steady_clock::now();
    cutter.dropAll(part, nullptr, 1);
    halves[k] = seconds(start);
  }
  std::printf("the raster's two halves on one thread: %.3f s and %.3f s (equal halves on two threads could reach "
              "%.2fx at best)\n", halves[0], halves[1], (halves[0] + halves[1]) / std::max(halves[0], halves[1]));
  double bestOne = 0.0;
  for (int threads : {1, 2}) {
    double best = 1e300;
    for (int repeat = 0; repeat < 5; ++repeat) {
      hsm::geometry::PointArray points = raster;
      const auto start = std::chrono::steady_clock::now();
      cutter.dropAll(points, nullptr, threads);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    const double rate = raster.rows() / best;
    std::printf("%d thread%s: %.3f s, %9.0f points/s, %.1f x OpenCAMLib's %d points/s\n", threads,
                threads > 1 ? "s" : " ", best, rate, rate / (threads == 1 ? 12000.0 : 24000.0),
                threads == 1 ? 12000 : 24000);
    if (threads == 1) bestOne = best;
    else std::printf("speed-up from one thread to two: %.2fx (chunks of 2,000 points taken in turn)\n", bestOne / best);
  }
  compareSpatialSearch(mesh, raster, 2.0);
  return 0;
}
