// Drop-cutter for a ball-end mill on a triangle mesh: for a tool axis along Z at (x, y), the lowest tool
// position that touches and does not penetrate any triangle (facet, edge and vertex contacts, as in
// OpenCAMLib's drop-cutter, with closed forms for each). Positions are of the tool tip (ball bottom).
#pragma once

#include "geometry/mesh.hpp"
#include "geometry/plan_grid.hpp"
#include "geometry/points.hpp"

#include <limits>
#include <vector>

namespace hsm::toolpath {

struct Contact {
  double z = -std::numeric_limits<double>::infinity();  // tool tip height; -inf: nothing under the tool
  int face = 0;                                         // face of the element that set it (0: unknown)
  bool touches() const { return z > -std::numeric_limits<double>::infinity(); }
};

inline constexpr size_t kMaxTriangles = 20000000;  // about 2 GB of index: the memory bound of a drop-cutter

class BallDropCutter {
public:
  BallDropCutter(const geometry::TriangleMesh& mesh, double radius);

  double radius() const { return radius_; }
  Contact drop(double x, double y) const;
  // Drops every point of `points` (x, y kept, z set; -inf where nothing is under the tool), on `threads`
  // threads (0: all cores). `faces`, if given, receives the contact face of each point.
  void dropAll(geometry::PointArray& points, std::vector<int>* faces = nullptr, int threads = 0) const;

private:
  struct Facet {
    double ax, ay, az, nx, ny, nz, d;  // plane n·p = d with nz > 0
    double e0x, e0y, e1x, e1y, det;    // plan basis for the inside test
    int face;
  };
  struct Edge {
    double ax, ay, az, ux, uy, length, slope;  // plan direction, plan length, dz per plan mm
    int face;
  };
  struct Vertex {
    double x, y, z;
    int face;
  };
  struct Cell {
    std::vector<int> facets, edges, vertices;
  };
  void addEdge(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int face);

  double radius_;
  std::vector<Facet> facets_;
  std::vector<Edge> edges_;
  std::vector<Vertex> vertices_;
  geometry::PlanGrid<Cell> grid_;  // cells of one radius: the ball at (x, y) reaches only its own cell's lists
};

}  // namespace hsm::toolpath
