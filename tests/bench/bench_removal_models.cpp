// The material-removal model chosen by measurement. The same case — the slanted slot block's S3
// path (the paper's Ø8 r1 torus), at 0.4 and 0.2 mm (or the resolutions given) — simulated by our tri-dexel model
// (roughing/removal.hpp) and by a narrow-band level set in OpenVDB (Debian's libopenvdb-dev, MPL-2.0): the
// stock and the part as level sets from their meshes, the tool meshed once, placed at each position by its
// transform, turned into a level set and subtracted (openvdb::tools::csgDifference), the volume by
// levelSetVolume. Printed: time, memory of the model, and the volume removed against the tri-dexel's finest.
// The tri-dexel runs on one thread; OpenVDB's tools on all cores (TBB): the times favour OpenVDB.
// Run: build/bin/bench_removal_models [resolution …]
#include "geometry/mesh.hpp"
#include "roughing/dexel.hpp"
#include "roughing/parts.hpp"
#include "roughing/removal.hpp"
#include "roughing/roughing.hpp"
#include "roughing/sweep.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/MeshToVolume.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <map>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace hsm;
using namespace hsm::roughing;

namespace {
double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

using Grid = openvdb::FloatGrid;

// The mesh's coincident corners welded (OCCT meshes each face apart: its inside and outside must be one
// watertight surface for OpenVDB to sign the distances), as a narrow-band level set.
Grid::Ptr levelSet(const geometry::TriangleMesh& mesh, const openvdb::math::Transform& transform) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::map<std::array<long long, 3>, unsigned> welded;
  std::vector<unsigned> index(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d& p = mesh.vertices[i];
    const std::array<long long, 3> key = {std::llround(p.x() * 1e5), std::llround(p.y() * 1e5), std::llround(p.z() * 1e5)};
    const auto [it, added] = welded.emplace(key, static_cast<unsigned>(points.size()));
    if (added) points.emplace_back(float(p.x()), float(p.y()), float(p.z()));  // world space: the transform maps it
    index[i] = it->second;
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const openvdb::Vec3I c(index[t[0]], index[t[1]], index[t[2]]);
    if (c[0] != c[1] && c[1] != c[2] && c[0] != c[2]) triangles.push_back(c);
  }
  return openvdb::tools::meshToLevelSet<Grid>(transform, points, triangles, 3.0f);
}

// The cutter of revolution as a closed mesh: bottom disk, corner arc, flutes' cylinder, top disk.
geometry::TriangleMesh cutterMesh(const Cutter& c, int around = 48) {
  std::vector<Eigen::Vector2d> profile = {{0.0, 0.0}};  // (radius, height) from the tip up
  const double R = c.radius(), r = c.kind == CutterKind::Flat ? 0.0 : c.kind == CutterKind::Ball ? R : c.cornerRadius;
  for (int k = 0; k <= 12; ++k) {
    const double phi = 0.5 * M_PI * k / 12;
    profile.push_back({R - r + r * std::sin(phi), r - r * std::cos(phi)});
  }
  profile.push_back({R, c.fluteLength});
  profile.push_back({0.0, c.fluteLength});
  geometry::TriangleMesh mesh;
  for (const Eigen::Vector2d& q : profile)
    for (int a = 0; a < around; ++a) {
      const double t = 2.0 * M_PI * a / around;
      mesh.vertices.emplace_back(q.x() * std::cos(t), q.x() * std::sin(t), q.y());
    }
  for (size_t k = 0; k + 1 < profile.size(); ++k)
    for (int a = 0; a < around; ++a) {
      const int b = (a + 1) % around;
      const int p0 = int(k * around + a), p1 = int(k * around + b), q0 = int((k + 1) * around + a), q1 = int((k + 1) * around + b);
      mesh.triangles.emplace_back(p0, q1, q0);  // outward: the profile goes up and out, then in at the top
      mesh.triangles.emplace_back(p0, p1, q1);
    }
  return mesh;
}

// The same positions as the tri-dexel's: the tip straight, the axis turned evenly, within the step.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> positions(const std::vector<ToolMove>& moves, double step,
                                                                   double length) {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> out = {{moves[0].tip, moves[0].axis}};
  for (size_t i = 1; i < moves.size(); ++i) {
    const double turn = std::acos(std::clamp(moves[i].axis.dot(moves[i - 1].axis), -1.0, 1.0));
    const int n = 1 + int(std::max((moves[i].tip - moves[i - 1].tip).norm(), turn * length) / step);
    for (int k = 1; k <= n; ++k) {
      const double f = double(k) / n;
      out.push_back({moves[i - 1].tip + f * (moves[i].tip - moves[i - 1].tip),
                     ((1 - f) * moves[i - 1].axis + f * moves[i].axis).normalized()});
    }
  }
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  openvdb::initialize();
  std::vector<double> resolutions;
  for (int k = 1; k < argc; ++k) resolutions.push_back(std::atof(argv[k]));
  if (resolutions.empty()) resolutions = {0.4, 0.2};
  const PartAndStock block = slantedSlotBlock();
  const VolumeToRemove volume = volumeToRemove(block.stock, block.part);
  const RemovalSolid& slot = volume.solids.front();
  const SweepSettings sweepSettings;
  const SweepResult paths = sweep(partition(slot, block.part, Strategy::SetupPlanes), slot, block.part, block.stock, sweepSettings);
  const Cutter& cutter = sweepSettings.cutter;
  std::printf("case: the slanted slot block's S3 path, %zu moves, volume to remove %.1f mm3 (closed form 15360)\n",
              paths.moves.size(), volume.volume);
  for (double h : resolutions) {
    RemovalSettings settings;
    settings.resolution = h;
    settings.threads = 1;
    auto start = std::chrono::steady_clock::now();
    const RemovalResult dexel = simulateRemoval(paths.moves, cutter, block.stock, block.part, settings);
    const double dexelTime = seconds(start);
    const double dexelRemoved = dexel.volumeToRemove - dexel.remainingVolume;
    // Memory of the tri-dexel: three models of rays (a vector each) and their intervals.
    const double dexelMb = 3.0 * dexel.rays * (sizeof(Intervals) + 0.5 * sizeof(Interval)) / 1e6;

    start = std::chrono::steady_clock::now();
    const openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(h);
    const double deflection = std::clamp(0.25 * h, 0.005, 0.05);
    Grid::Ptr material = levelSet(geometry::meshFacesAfresh(block.stock, deflection), *transform);
    Grid::Ptr part = levelSet(geometry::meshFacesAfresh(block.part, deflection), *transform);
    std::printf("  OpenVDB at %.1f mm: stock %.1f mm3, part %.1f mm3 (box %.1f)\n", h, openvdb::tools::levelSetVolume(*material),
                openvdb::tools::levelSetVolume(*part), 80.0 * 40.0 * 30.0);
    std::fflush(stdout);
    openvdb::tools::csgDifference(*material, *part);
    const double vdbBefore = openvdb::tools::levelSetVolume(*material);
    const geometry::TriangleMesh tool = cutterMesh(cutter);
    const double step = std::min(4.0 * h, std::sqrt(2.0 * cutter.cornerRadius * h));
    const auto places = positions(paths.moves, step, cutter.fluteLength);
    for (const auto& [tip, axis] : places) {
      const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis);
      geometry::TriangleMesh placed = tool;
      for (Eigen::Vector3d& p : placed.vertices) p = tip + turn * p;
      Grid::Ptr cut = levelSet(placed, *transform);
      openvdb::tools::csgDifference(*material, *cut);
    }
    const double vdbTime = seconds(start);
    const double vdbRemoved = vdbBefore - openvdb::tools::levelSetVolume(*material);
    std::printf("%.1f mm: tri-dexel %.2f s, %.0f MB, removed %.1f mm3 (V_r %.2f %%) | OpenVDB level set %.2f s, %.1f MB, "
                "removed %.1f mm3 (volume to remove %.1f mm3) | %zu positions, time ratio %.1f\n",
                h, dexelTime, dexelMb, dexelRemoved, dexel.remainingShare, vdbTime, material->memUsage() / 1e6,
                vdbRemoved, vdbBefore, places.size(), vdbTime / dexelTime);
    std::fflush(stdout);
  }
  return 0;
}
