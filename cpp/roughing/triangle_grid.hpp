// Triangles of a mesh bucketed in a uniform grid of cubes (internal to the roughing): the ones near a tool
// position for the clearance check, the distance from a point to the mesh for the stock a roughing leaves.
#pragma once

#include "geometry/mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace hsm::roughing {

// The distance from p to the triangle a, b, c (its nearest point: inside, on an edge or a corner).
double pointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c);

// The distance from p to the segment a–b.
inline double segmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * d - p).norm();
}

// Triangles bucketed in a uniform grid of cubes, for the ones near a tool position.
class TriangleGrid {
public:
  TriangleGrid(const geometry::TriangleMesh& mesh, double cell) : mesh_(mesh), cell_(cell) {
    centres_.reserve(mesh.triangles.size());
    radii_.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      Eigen::AlignedBox3d box;
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        box.extend(mesh.vertices[mesh.triangles[t][k]]);
        centre += mesh.vertices[mesh.triangles[t][k]] / 3.0;
      }
      double radius = 0.0;
      for (int k = 0; k < 3; ++k) radius = std::max(radius, (mesh.vertices[mesh.triangles[t][k]] - centre).norm());
      centres_.push_back(centre);
      radii_.push_back(radius);
      forCells(box, [&](long key, const Eigen::Vector3d&) { cells_[key].push_back(static_cast<int>(t)); });
    }
  }

  // Every triangle within `radius` of the segment a–b (by its cell, then by its bounding sphere), each once
  // (`seen` is scratch space of the mesh's size).
  template <class Visit>
  void near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, std::vector<int>& seen, int stamp,
            Visit&& visit) const {
    Eigen::AlignedBox3d box(a.cwiseMin(b), a.cwiseMax(b));
    box.min().array() -= radius;
    box.max().array() += radius;
    const double cellReach = radius + 0.5 * std::sqrt(3.0) * cell_;
    forCells(box, [&](long key, const Eigen::Vector3d& centre) {
      if (segmentDistance(centre, a, b) > cellReach) return;
      const auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (int t : it->second)
        if (seen[t] != stamp) {
          seen[t] = stamp;
          if (segmentDistance(centres_[t], a, b) <= radius + radii_[t]) visit(t);
        }
    });
  }

  // Triangle t's centroid and the radius of the sphere about it that holds the triangle.
  const Eigen::Vector3d& centre(int t) const { return centres_[t]; }
  double boundingRadius(int t) const { return radii_[t]; }

private:
  template <class Each>
  void forCells(const Eigen::AlignedBox3d& box, Each&& each) const {
    const Eigen::Vector3i lo = (box.min() / cell_).array().floor().cast<int>();
    const Eigen::Vector3i hi = (box.max() / cell_).array().floor().cast<int>();
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) each(key(i, j, k), Eigen::Vector3d((i + 0.5) * cell_, (j + 0.5) * cell_, (k + 0.5) * cell_));
  }
  static long key(int i, int j, int k) {
    return (static_cast<long>(i) & 0x1FFFFF) | ((static_cast<long>(j) & 0x1FFFFF) << 21) |
           ((static_cast<long>(k) & 0x1FFFFF) << 42);
  }
  const geometry::TriangleMesh& mesh_;
  double cell_;
  std::unordered_map<long, std::vector<int>> cells_;
  std::vector<Eigen::Vector3d> centres_;  // per triangle: the centroid and the radius that holds it
  std::vector<double> radii_;
};

// The distance from p to the mesh of `grid`, or `limit` when no triangle is nearer than that.
double distanceToMesh(const TriangleGrid& grid, const geometry::TriangleMesh& mesh, const Eigen::Vector3d& p,
                      double limit, std::vector<int>& seen, int stamp);

}  // namespace hsm::roughing
