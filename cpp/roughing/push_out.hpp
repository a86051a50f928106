// A level's domain pushed out to the cutter's real clearance (internal to the roughing). The keep-out of the
// sweep (flat.hpp) holds the tool's centre from the part by the widest the tool is over each band of heights
// and over bins of the plane's scales, on the safe side: where the part bounds a level, its outer pass stands
// up to a millimetre farther from the part than the allowance asks, and leaves that much stock. Each point of
// the domain's boundary is moved outward, along its normal laid flat, as far as the cutter there keeps the
// clearance from the part's triangles (tool_distance.hpp: exact, with the tool's axis where it stands).
#pragma once

#include "geometry/mesh.hpp"
#include "roughing/projection.hpp"
#include "roughing/sweep.hpp"
#include "roughing/triangle_grid.hpp"

#include <limits>

namespace hsm::roughing {

struct PushSettings {
  double clearance = 0.5;  // mm: the least distance from the cutter to the part's triangles
  // Height above the tip under which the part is left out: a floor the level stands the allowance over.
  double lowest = -std::numeric_limits<double>::infinity();
  double most = 1.5;      // true mm: the farthest a point of the boundary moves
  double spacing = 0.25;  // true mm between the boundary's points, at most
  int threads = 0;        // 0: all cores
};

// The part's triangles and their grid, built once for every level of a sweep.
struct PartTriangles {
  explicit PartTriangles(geometry::TriangleMesh triangles);
  PartTriangles(const PartTriangles&) = delete;  // the grid holds the mesh by reference
  PartTriangles& operator=(const PartTriangles&) = delete;
  geometry::TriangleMesh mesh;
  TriangleGrid grid;
};

// `domain` (where the centre may go, with its tip at height `tip` of the projection's level) grown by its
// boundary's points pushed out, then cut to `within` (the slice: a boundary that is the slice's own, not the
// part's, goes no farther). InputError for a clearance below 0, a `most` outside ]0, 10] mm, a spacing outside
// [0.01, 10] mm, or more than a million boundary points.
cl::Paths pushedOut(const cl::Paths& domain, const cl::Paths& within, double tip, const Projection& projection,
                    const PartTriangles& part, const Cutter& cutter, const PushSettings& settings);

}  // namespace hsm::roughing
