// Drop-cutter throughput against OpenCAMLib 2022.12's BatchDropCutter on the same raster (DESIGN.md):
// Ø4 mm ball on shared/data/wavy_surface.stl (19k triangles), 0.4 mm stepover × 0.05 mm sampling, 423k
// points; OpenCAMLib about 12,000 points/s on one core and 24,000 on two. Run: build/bin/bench_dropcutter
#include "toolpath/dropcutter.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace hsm::toolpath;

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
  for (int threads : {1, 2}) {
    double best = 1e300;
    for (int repeat = 0; repeat < 3; ++repeat) {
      hsm::geometry::PointArray points = raster;
      const auto start = std::chrono::steady_clock::now();
      cutter.dropAll(points, nullptr, threads);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    const double rate = raster.rows() / best;
    std::printf("%d thread%s: %.3f s, %9.0f points/s, %.1f x OpenCAMLib's %d points/s\n", threads,
                threads > 1 ? "s" : " ", best, rate, rate / (threads == 1 ? 12000.0 : 24000.0),
                threads == 1 ? 12000 : 24000);
  }
  return 0;
}
