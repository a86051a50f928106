// A tri-dexel model of material (internal to the material-removal simulation, removal.hpp): three grids of
// parallel rays, along X, Y and Z, `resolution` mm apart; each ray keeps the intervals along it that are
// inside the material. A solid is read from a closed triangle mesh by its crossings with each ray (even-odd);
// removal subtracts intervals. Volumes are measured on the Z rays (length × resolution²); the three
// directions give the thickness of material along any normal within 55° of one of them.
#pragma once

#include "geometry/mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace hsm::roughing {

struct Interval {
  double from, to;
};
using Intervals = std::vector<Interval>;

// [from, to] taken out of `intervals` (sorted, disjoint); returns the length taken.
double subtract(Intervals& intervals, double from, double to);
// Length of the overlap of [from, to] with the intervals.
double overlap(const Intervals& intervals, double from, double to);

class TriDexel {
public:
  // Rays over `box` (grown by one spacing), `resolution` apart; at most `maxRays` in all (InputError beyond:
  // the message says the resolution that fits).
  TriDexel(const Eigen::AlignedBox3d& box, double resolution, long maxRays);

  // The intervals inside the closed mesh, on every ray (the rays sit at cell centres, offset by a fraction
  // of a micrometre so that none runs exactly through a mesh's edge); on `threads` threads (0: all cores).
  void fill(const geometry::TriangleMesh& mesh, int threads = 1);
  // This model minus `other` (the same grid).
  void subtract(const TriDexel& other, int threads = 1);
  // This model made `other`'s (the same grid), on `threads` threads.
  void assign(const TriDexel& other, int threads = 1);

  double resolution() const { return h_; }
  long rays() const;
  double volume() const;  // mm³, on the Z rays
  // Ray (i, j) of direction k (0: X, 1: Y, 2: Z): u and v are axes (k+1)%3 and (k+2)%3.
  int count(int k, int axis) const { return n_[k][axis]; }
  const Intervals& at(int k, int i, int j) const { return rays_[k][index(k, i, j)]; }
  // A bound of ray (i, j)'s material kept beside the rays in floats: from ≤ its first interval's start, to ≥
  // its last one's end (from > to: none). Read in turn along a row without following each ray's intervals
  // elsewhere in memory, it tells most rays a tool crosses that it cannot meet their material.
  struct Extent {
    float from, to;
  };
  Extent extent(int k, int i, int j) const { return extents_[k][index(k, i, j)]; }
  const Extent* extents(int k, int j) const { return &extents_[k][index(k, 0, j)]; }  // row j's, in turn
  // [from, to] taken out of ray (i, j) of direction k, its extent kept: the length taken.
  double remove(int k, int i, int j, double from, double to);
  // Where ray (i, j) of direction k runs: its point at coordinate 0 along k (inline: the simulation asks it
  // for every ray a tool crosses).
  Eigen::Vector3d origin(int k, int i, int j) const {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p[(k + 1) % 3] = across(k, i);
    p[(k + 2) % 3] = low_[(k + 2) % 3] + j * h_ + jitter_[k][1];
    return p;
  }
  // Its coordinate u (along a row).
  double across(int k, int i) const { return low_[(k + 1) % 3] + i * h_ + jitter_[k][0]; }
  // The material as a closed mesh of blocks: one column per `stride` × `stride` Z rays (the middle one's
  // intervals), its top and bottom, and its sides where the neighbouring column has no material. Its volume
  // is the columns' (Σ length × (stride·resolution)²).
  geometry::TriangleMesh blocks(int stride) const;
  // Whether p lies in the material of the Z ray nearest it (false outside the grid).
  bool inside(const Eigen::Vector3d& p) const;
  // The index range [first, last] of rays of direction k whose (u, v) lies in the box's projection.
  void rangeOf(int k, const Eigen::AlignedBox3d& box, int& i0, int& i1, int& j0, int& j1) const;

private:
  size_t index(int k, int i, int j) const { return static_cast<size_t>(j) * n_[k][0] + i; }
  void fillRows(const geometry::TriangleMesh& mesh, int k, int from, int to);  // rows [from, to) of direction k
  void keepExtent(int k, size_t r);

  double h_;
  Eigen::Vector3d low_;
  int n_[3][2];                          // per direction: rays along u and along v
  double jitter_[3][2];
  std::vector<Intervals> rays_[3];
  std::vector<Extent> extents_[3];
};

}  // namespace hsm::roughing
