#include "toolpath/dropcutter.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <thread>
#include <utility>

namespace hsm::toolpath {

namespace {
constexpr double kVertical = 1e-9;  // facets this close to vertical are reached through their edges only
}

BallDropCutter::BallDropCutter(const geometry::TriangleMesh& mesh, double radius) : radius_(radius) {
  if (!(radius > 0.0)) throw InputError("ball radius must be positive, got " + std::to_string(radius) + " mm");
  if (mesh.triangles.empty() && mesh.polylines.empty())
    throw InputError("the mesh has no triangle: nothing to drop the tool on");
  if (mesh.triangles.size() > kMaxTriangles)
    throw InputError("the part meshes into " + std::to_string(mesh.triangles.size()) + " triangles, more than the " +
                     std::to_string(kMaxTriangles) + " the drop-cutter takes: use a larger mesh deflection, or "
                     "finish the face of a part with fewer faces around it");
  Eigen::AlignedBox3d box = mesh.bounds();
  for (const auto& line : mesh.polylines)
    for (const auto& p : line) box.extend(p);
  const Eigen::AlignedBox2d plan(box.min().head<2>(), box.max().head<2>());
  grid_ = geometry::PlanGrid<Cell>(plan, std::max(radius, 1e-3), radius,
                                   "the part (for a " + std::to_string(2.0 * radius) + " mm tool)");

  // Polylines: their points are vertices, their chords edges.
  for (size_t l = 0; l < mesh.polylines.size(); ++l) {
    const auto& line = mesh.polylines[l];
    const int face = l < mesh.polylineFace.size() ? mesh.polylineFace[l] : 0;
    for (size_t k = 0; k < line.size(); ++k) {
      const Eigen::Vector3d& v = line[k];
      const int id = static_cast<int>(vertices_.size());
      vertices_.push_back({v.x(), v.y(), v.z(), face});
      grid_.forBox(v.x(), v.y(), v.x(), v.y(), [&](Cell& cell) { cell.vertices.push_back(id); });
      if (k == 0) continue;
      addEdge(line[k - 1], v, face);
    }
  }
  std::map<std::pair<int, int>, int> edgeIndex;  // unique edges (by vertex pair)
  std::vector<char> vertexSeen(mesh.vertices.size(), 0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const int face = t < mesh.faceOf.size() ? mesh.faceOf[t] : 0;
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    const double xmin = std::min({a.x(), b.x(), c.x()}), xmax = std::max({a.x(), b.x(), c.x()});
    const double ymin = std::min({a.y(), b.y(), c.y()}), ymax = std::max({a.y(), b.y(), c.y()});
    Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() > 0.0) {
      n.normalize();
      if (n.z() < 0) n = -n;
      const double det = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
      if (n.z() > kVertical && std::abs(det) > 0.0) {
        const int id = static_cast<int>(facets_.size());
        facets_.push_back({a.x(), a.y(), a.z(), n.x(), n.y(), n.z(), n.dot(a), b.x() - a.x(), b.y() - a.y(),
                           c.x() - a.x(), c.y() - a.y(), det, face});
        grid_.forBox(xmin, ymin, xmax, ymax, [&](Cell& cell) { cell.facets.push_back(id); });
      }
    }
    for (int k = 0; k < 3; ++k) {
      int p = tri[k], q = tri[(k + 1) % 3];
      if (!vertexSeen[p]) {
        vertexSeen[p] = 1;
        const Eigen::Vector3d& v = mesh.vertices[p];
        const int id = static_cast<int>(vertices_.size());
        vertices_.push_back({v.x(), v.y(), v.z(), face});
        grid_.forBox(v.x(), v.y(), v.x(), v.y(), [&](Cell& cell) { cell.vertices.push_back(id); });
      }
      if (p > q) std::swap(p, q);
      if (edgeIndex.count({p, q})) continue;
      edgeIndex[{p, q}] = 1;
      addEdge(mesh.vertices[p], mesh.vertices[q], face);
    }
  }
}

void BallDropCutter::addEdge(const Eigen::Vector3d& A, const Eigen::Vector3d& B, int face) {
  const double length = std::hypot(B.x() - A.x(), B.y() - A.y());
  if (length < 1e-12) return;  // vertical: its end vertices cover it
  const int id = static_cast<int>(edges_.size());
  edges_.push_back({A.x(), A.y(), A.z(), (B.x() - A.x()) / length, (B.y() - A.y()) / length, length,
                    (B.z() - A.z()) / length, face});
  grid_.forBox(std::min(A.x(), B.x()), std::min(A.y(), B.y()), std::max(A.x(), B.x()), std::max(A.y(), B.y()),
              [&](Cell& cell) { cell.edges.push_back(id); });
}

Contact BallDropCutter::drop(double x, double y) const {
  Contact best;
  const Cell* cell = grid_.at(x, y);
  if (!cell) return best;
  const double r = radius_, r2 = r * r;
  double top = -std::numeric_limits<double>::infinity();  // highest ball centre
  int face = 0;
  for (int id : cell->facets) {
    const Facet& f = facets_[id];
    // Contact point of the ball on the facet's plane, in plan; inside the triangle?
    const double qx = x - r * f.nx - f.ax, qy = y - r * f.ny - f.ay;
    const double s = (qx * f.e1y - qy * f.e1x) / f.det, t = (f.e0x * qy - f.e0y * qx) / f.det;
    if (s < 0.0 || t < 0.0 || s + t > 1.0) continue;
    const double z = (f.d - f.nx * (x - r * f.nx) - f.ny * (y - r * f.ny)) / f.nz + r * f.nz;
    if (z > top) {
      top = z;
      face = f.face;
    }
  }
  for (int id : cell->edges) {
    const Edge& e = edges_[id];
    const double wx = x - e.ax, wy = y - e.ay;
    const double a = wx * e.ux + wy * e.uy;
    const double b2 = wx * wx + wy * wy - a * a;
    if (b2 >= r2) continue;
    const double rho = std::sqrt(r2 - b2);
    const double root = std::sqrt(1.0 + e.slope * e.slope);
    const double s = a + e.slope * rho / root;  // where the ball touches the edge, along it
    if (s < 0.0 || s > e.length) continue;       // beyond an end: the end vertex decides
    const double z = e.az + e.slope * a + rho * root;
    if (z > top) {
      top = z;
      face = e.face;
    }
  }
  for (int id : cell->vertices) {
    const Vertex& v = vertices_[id];
    const double d2 = (x - v.x) * (x - v.x) + (y - v.y) * (y - v.y);
    if (d2 > r2) continue;
    const double z = v.z + std::sqrt(r2 - d2);
    if (z > top) {
      top = z;
      face = v.face;
    }
  }
  if (top > -std::numeric_limits<double>::infinity()) {
    best.z = top - r;
    best.face = face;
  }
  return best;
}

void BallDropCutter::dropAll(geometry::PointArray& points, std::vector<int>* faces, int threads) const {
  const Eigen::Index n = points.rows();
  if (faces) faces->assign(static_cast<size_t>(n), 0);
  parallelChunks(static_cast<long>(n), threads, 2000, [&](long from, long to) {
    for (Eigen::Index i = from; i < to; ++i) {
      const Contact c = drop(points(i, 0), points(i, 1));
      points(i, 2) = c.z;
      if (faces) (*faces)[static_cast<size_t>(i)] = c.face;
    }
  });
}

}  // namespace hsm::toolpath
