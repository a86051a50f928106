// 5-axis roughing, part 3: material-removal simulation of a toolpath, independent of the path's generator.
//
// The stock less the part is a tri-dexel model (dexel.hpp: rays along X, Y and Z `resolution` apart, the
// intervals of material on each), the part a second one that is never cut (a tool entering it is a gouge).
// The tool is swept through it move by move: the tip goes straight and the axis turns evenly between a move's
// ends (as a controller interpolates orientation), sampled so that neighbouring positions are at most
// 4 × resolution apart at the tip and at the flutes' end — and never farther than leaves a ridge of a quarter
// resolution between the scallops of the corner radius (s²/8r ≤ resolution/4). At each position the cutter (flat, torus or
// ball, over its flute length: a solid of revolution of cylinders, cones for a torus's corner within 5 µm of
// it, and a sphere) takes its intervals out of every ray it crosses. The shank and holder do not cut: they
// give the stick-out.
//
// Why tri-dexel, measured (tests/bench/bench_removal_models.cpp, the slanted slot's S3 path, this 2-core machine,
// 2 December 2026): against a narrow-band level set in OpenVDB (a level set of the tool per position,
// csgDifference; its tools on both cores, ours on one), 0.34 against 29.3 s at 0.4 mm and 1.5 against 112 s at
// 0.2 mm (75-87 times faster), 17 against 30 MB at 0.2 mm, the removed volumes within 0.1-0.2 % of each other,
// but the level sets' stock − part came out 16,625-17,878 mm³ for the exact 15,360 (a sliver at every face the
// part shares with the stock), where the dexels' is exact: an interval end is exact along its ray (a floor or a
// wall between rays is not rounded to a voxel), and removal is a 1-D subtraction per ray. A faster level-set
// use (one tool grid resampled per position) would narrow the time ratio, not the shared-face error.
//
// Measured, per program (the paper's Table 1 and beyond):
//   remaining share V_r   stock left of the volume to remove, % (Z rays); also without the allowance layer
//                         left on the part (the stock on the part below), which a roughing leaves on purpose;
//   path lengths          all moves, feed moves (not rapids), and the feed moves in material: a position is in
//                         material when it takes out a chip of at least `chipSection` mm² × the step;
//   stick-out L_tool      every `stickOutSpacing` mm of path, the highest point of the part or of the stock
//                         left at that time within the holder's radius of the axis, above the tip along it
//                         (read on every other ray each way): the least stick-out at which the holder touches
//                         nothing there;
//   gouge                 the part's volume the cutter enters (Z rays), the first move that does and where;
//   rapids in stock       every rapid (G0) that takes material out of the stock left at that time: a fault (a
//                         rapid through material breaks tools), with where it first cuts and how much;
//   stock on the part     at points of the part's surface about 2 resolutions apart, the thickness of material
//                         left along the outward normal
//                         (read on the ray direction nearest the normal, × its cosine): mean, max, standard
//                         deviation weighted by area (Krimpenis 2009), and the values for a map.
#pragma once

#include "common/progress.hpp"
#include "geometry/mesh.hpp"
#include "roughing/sweep.hpp"

#include <Eigen/Core>
#include <TopoDS_Shape.hxx>

#include <vector>

namespace hsm::roughing {

struct RemovalSettings {
  double resolution = 0.2;       // mm between rays
  double chipSection = 0.1;      // mm²: the least chip section of a position "in material"
  double stickOutSpacing = 5.0;  // mm of path between stick-out measures
  double allowance = 0.5;        // mm of stock meant to stay on the part: V_r is also given without it
  int stockMeshStride = 0;       // > 0: the stock left as a mesh of blocks of stride × stride Z rays (0: none)
  double restSpacing = 0.0;      // > 0: the stock left beyond the allowance as points about this far apart (mm)
  int threads = 0;               // 0: all cores
  ProgressCallback progress;
};

// A rapid that cuts the stock left: the move, where along it the tool first takes material out (the tip, and
// the share of the move's length before it), and the volume it takes out (Z rays), mm³.
struct RapidFault {
  int move = -1;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  double along = 0.0;
  double volume = 0.0;
};

struct RemovalResult {
  double resolution = 0.0;                           // mm, reported with every figure
  double volumeToRemove = 0.0, remainingVolume = 0.0; // mm³
  double remainingShare = 100.0;                     // % of the volume to remove left (V_r)
  // The same without the allowance layer that is left (Σ area × min(thickness, allowance) over the samples):
  // the material the strategy did not reach.
  double beyondAllowanceVolume = 0.0, beyondAllowanceShare = 100.0;
  double pathLength = 0.0, feedLength = 0.0, inMaterialLength = 0.0;  // mm
  double inMaterialShare = 0.0;                      // % of the feed length
  double inMaterialPathShare = 0.0;                  // % of the whole path: rapids and links count too
  double stickOut = 0.0;                             // mm: least stick-out so that the holder clears everything
  int stickOutMove = -1;                             // the move that needs it
  double gougeVolume = 0.0;                          // mm³ of the part cut
  int gougeMove = -1;                                // first move that gouges
  Eigen::Vector3d gougeAt = Eigen::Vector3d::Zero(); // where (the tip there)
  std::vector<RapidFault> rapidFaults;               // in the order of the moves
  double rapidVolume = 0.0;                          // mm³ taken out by rapids, all faults
  // Stock left on the finished surfaces, at sample points of them (outward normal thickness, mm).
  std::vector<Eigen::Vector3d> surfacePoints;
  std::vector<double> thickness, weight;             // weight: the sample's share of area, mm²
  double thicknessMean = 0.0, thicknessMax = 0.0, thicknessStd = 0.0;
  long rays = 0, positions = 0;
  // The stock left (stockMeshStride > 0): closed, blocks of stride × resolution a side; for FreeCAD and STL.
  geometry::TriangleMesh stockMesh;
  // The stock left farther from the part than the allowance and half a spacing (restSpacing > 0), on Z rays a
  // whole number of resolutions apart: what a rest-roughing operation is to take out.
  RestStock rest;
};

// One tool's moves: a program of several operations runs them in turn, each with its own cutter, on the same
// stock (roughing, then rest roughing with a smaller tool). Move indices in a result count through them all.
struct ToolRun {
  std::vector<ToolMove> moves;
  Cutter cutter;
};

// The moves swept through stock − part. InputError for a resolution outside [0.005, 50] mm or one that needs
// more than 10 million rays per model, a chip section or stick-out spacing that is not positive, moves that would need
// more than 10 million tool positions, an empty stock; Cancelled when `progress` says stop.
RemovalResult simulateRemoval(const std::vector<ToolMove>& moves, const Cutter& cutter, const TopoDS_Shape& stock,
                              const TopoDS_Shape& part, const RemovalSettings& settings = {});
// The operations in turn; the stick-out is the largest any of them needs. InputError for a rest spacing
// outside 0 (none) or [resolution, 20] mm, or one that gives more than 5 million points.
RemovalResult simulateRemoval(const std::vector<ToolRun>& runs, const TopoDS_Shape& stock, const TopoDS_Shape& part,
                              const RemovalSettings& settings = {});

// The moves with every rapid of `faults` split where it meets the stock left: a rapid to `margin` mm (and the
// simulation's sampling step) before the first position that cut, then the rest of the move as a plunge (the
// entry feed). What in-process-stock-aware links do in CAM: approach fast through the air, slowly into what is
// still there. Faults must be of these moves (simulateRemoval of them): InputError otherwise.
std::vector<ToolMove> feedThroughStock(const std::vector<ToolMove>& moves, const std::vector<RapidFault>& faults,
                                       double margin);

// The moves simulated at settings.resolution — after the operations `before`, on the stock they left — and fed
// through the stock left where a rapid would cut it (feedThroughStock, `margin` mm): the program whose rapids
// keep out of the stock, and the faults it mended (move indices of these moves).
struct RapidsMended {
  std::vector<ToolMove> moves;
  std::vector<RapidFault> mended;
};
RapidsMended keepRapidsOutOfStock(const std::vector<ToolMove>& moves, const Cutter& cutter, const TopoDS_Shape& stock,
                                  const TopoDS_Shape& part, const RemovalSettings& settings, double margin = 1.0,
                                  const std::vector<ToolRun>& before = {});

}  // namespace hsm::roughing
