// What a roughing path leaves, split by cause, measured apart from the sweep that made it: of the material of a
// sub-volume's solid, what a straight tool along the path's own axes cannot reach at all without coming nearer
// the part than the allowance, and what it reaches only from heights between the path's levels. The rest of
// what the path leaves (the material-removal simulation's V_r less these two) is the path's own: material a
// tool at one of its levels could have taken.
//
// The measure works on the partition's slicing laid flat (projection.hpp: the tool axis along each column, the
// height along it), on a grid of `resolution` mm:
//   the part's top   per column, the highest point of the part's surface (sampled from its triangles);
//   envelope e(q)    the lowest tip height at column q where the cutter grown by the allowance touches no
//                    part point: the largest over part points within its reach of their height less the grown
//                    cutter's lowest height at their distance from the axis (a drop-cutter of the part's
//                    heights, distances in true mm over the plane's scales at each point);
//   floor F(q')      the lowest point the tool reaches in column q' from any column within its radius, the tip
//                    at the envelope there: material below it is out of reach;
//   levels           the distinct tip heights of the path's cuts; from each column the tool reaches only as low
//                    as the lowest level above its envelope, which gives a floor F_L ≥ F;
// and the solid's material is integrated column by column (its tri-dexel model, the volume element from the
// projection's own derivatives). The holder is ignored, as the setup search (S3) ignores it.
#pragma once

#include "roughing/roughing.hpp"
#include "roughing/sweep.hpp"

#include <TopoDS_Shape.hxx>

#include <vector>

namespace hsm::roughing {

struct LeftSplit {
  double resolution = 0.0;     // mm, the grid of columns and of heights
  double volume = 0.0;         // mm³ of the solid's material as sampled
  double unreachable = 0.0;    // mm³ below the floor: no tool position along these axes reaches it
  double betweenLevels = 0.0;  // mm³ between the floor and the floor from the path's levels
  int levels = 0;              // the path's distinct cutting heights
};

// The split for the moves that sweep `solid` as `partition` slices it (one region's sweep, before it is joined
// to others). InputError for a resolution outside [0.1, 5] mm, or one that needs more than 100 million samples
// (naming the resolution that fits); threads: 0 for all cores.
LeftSplit splitWhatIsLeft(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part,
                          const Cutter& cutter, double allowance, const std::vector<ToolMove>& moves,
                          double resolution = 0.25, int threads = 0);

}  // namespace hsm::roughing
