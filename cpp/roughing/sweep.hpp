// 5-axis roughing, part 2: sweeping the sub-volumes of a partition (roughing.hpp) into toolpaths.
//
// Each sub-volume is swept by contour-parallel passes ("offsets of the boundaries", Chen 2011) on its slicing
// surface, the tool axis normal to it with zero lead and tilt (the paper's choice): planes (S1, S3: 3-axis and
// 3+2-axis paths, one fixed tool axis), coaxial cylinders (S2: 4-axis paths, the axis radial) unrolled at each
// level's radius, and offsets of a surface of revolution (S4, S5: 5-axis paths) laid flat (projection.hpp).
//
// A slice lies between two surfaces; on its main level the tool's tip sits on the far one (the tool axis
// points out through the near one, towards the spindle) and clears the slice's material above it. At a level,
// laid flat:
//   region    the slice projected along the tool axis (its triangles laid flat and united);
//   shadow    the part wherever it stands above the tip's surface, or within the allowance below it, projected
//             along the tool axis, in layers of height: the part just above the tip is met by the corner of a
//             torus or ball, narrower than the flutes, so each layer keeps the centre only as far away as the
//             tool grown by the allowance is wide there (flat.hpp's bands);
//   domain    region shrunk by the tool radius less an overhang of 10 % of the diameter (the outer pass goes
//             slightly past the slice's outline, through the crossable faces), minus the shadow grown so, and
//             by the mesh's deflection: where the tool's centre may go;
//   passes    the domain's boundary, then its offsets inwards every radial step (the radial engagement times
//             the diameter), closed loops from the outside in, and rings between where the last would leave an
//             island in the middle beyond the reach of the tool's bottom.
// Step-up (step_up.hpp): where the part within a slice leans, the domain grows from the far side to the near
// one, and the main level alone would leave a staircase step as high as the slice on every leaning wall and
// floor. Intermediate levels are added between (halving the slice while the step left across a wall is over
// `stepUpScallop` and the levels stay `stepUpMinimum` apart) and cut from the near side down after the main
// level, each only where its domain reaches beyond the main level's: open passes that start and end inside
// what the main level cleared (entered by a plunge there), or whole loops (entered by a ramp) where the main
// level had no room at all.
// 2-D offsets and booleans are Clipper's (Debian's libpolyclipping, Boost licence), in integers of 0.1 µm;
// bench_roughing compares them with OCCT's planar offset (BRepOffsetAPI_MakeOffset) on the same regions.
//
// Links: from a pass to the next, a straight move at the level when it stays in the domain, else a retract
// along the tool axis to `clearance` above the stock, a rapid over, and back down. Entries: a plunge where the
// tool's disk at the entry lies outside the slice's material (its region) or in what a lower level cleared,
// else a ramp along the loop at most `rampAngleDeg` steep from the level above (a torus or flat tool does not
// plunge into full material). Slices are taken from the crossable face inwards, so that every level is entered
// from cleared material.
#pragma once

#include "common/progress.hpp"
#include "roughing/roughing.hpp"

#include <Eigen/Core>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace hsm::roughing {

enum class CutterKind { Flat, Torus, Ball };

// The cutter and what holds it, mm. The radius of the cutter at a height h above its tip is `profileRadius`.
struct Cutter {
  CutterKind kind = CutterKind::Torus;
  double diameter = 8.0;       // the paper's FRAISA torus: Ø8, corner radius 1
  double cornerRadius = 1.0;   // flat: 0; ball: diameter / 2
  double fluteLength = 20.0;   // cutting length from the tip
  double shankDiameter = 8.0;
  double stickOut = 40.0;      // from the tip to the holder
  double holderDiameter = 32.0, holderLength = 40.0;
  double radius() const { return 0.5 * diameter; }
  double corner() const;  // the radius of its bottom's rounding: 0 flat, the corner's torus, the radius ball
  double profileRadius(double h) const;
};
std::string cutterKindName(CutterKind kind);
// InputError naming the field for a cutter that cannot exist (a corner radius beyond the radius, a flute
// longer than the stick-out, a shank wider than the holder…) or sizes out of 0.1–100 mm.
void checkCutter(const Cutter& cutter);

struct SweepSettings {
  Cutter cutter;
  double radialEngagement = 0.7;  // radial step between neighbouring passes, as a share of the diameter
  double allowance = 0.5;         // mm of stock left on the part
  double tolerance = 0.01;        // mm: chords of the passes and of the shapes' sections
  double rampAngleDeg = 3.0;      // entries into material ramp at most this steep
  double clearance = 5.0;         // mm beyond the stock along the tool axis where links travel
  double meshDeflection = 0.05;   // mm: the part's triangles, for its shadow (added to the allowance)
  // Intermediate levels inside each slice where the part leans (step-up): added while the staircase a wall
  // would keep is thicker than `stepUpScallop` across it, never nearer than `stepUpMinimum` to each other
  // (mm; 0: none, each slice cut at its far side only, as the paper does).
  double stepUpMinimum = 1.0;
  double stepUpScallop = 0.25;
  // Push-out: how far (true mm) each level's boundary may move towards the part, from where the keep-out
  // (on the safe side, up to a millimetre wide) put it, to the cutter's exact clearance on the part's
  // triangles (push_out.hpp). 0: off. The outer passes then leave no more than the allowance where the tool
  // reaches; the sweep takes up to half as long again.
  double pushOutMost = 1.5;
  // Rest roughing: each level cuts only where its tool reaches this stock (the removal simulation of the
  // operations before); empty: everything.
  RestStock rest;
  ProgressCallback progress;
};

enum class MoveKind { Rapid, Plunge, Ramp, Cut, Link };
std::string moveKindName(MoveKind kind);

// The tool's tip (its lowest point along the axis) and its axis (unit, from the tip towards the spindle), in
// the part's frame, at the end of a move; moves are straight.
struct ToolMove {
  MoveKind kind = MoveKind::Cut;
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  int subVolume = -1;  // index in the partition's sub-volumes (−1 for links between them)
};

// One closed pass at a level, as swept: for the checks of the tests and the pictures.
struct Pass {
  int subVolume = 0, ring = 0;               // ring: 0 for the domain's boundary, k for its k-th offset
  std::vector<Eigen::Vector3d> points;       // the tip's loop (first point not repeated), or open path
  bool closed = true;                        // a loop, or an open path from its first point to its last
  bool intermediate = false;                 // on a level between a slice's far and near sides (step-up)
  double depth = 0.0;                        // the ring's offset inward from the level's domain, mm laid flat
};

struct SweepResult {
  std::vector<ToolMove> moves;               // from the first entry to the last retract
  std::vector<Pass> passes;
  double cuttingLength = 0.0, rampLength = 0.0, linkLength = 0.0, rapidLength = 0.0;  // mm
  int retracts = 0, ramps = 0, plunges = 0;
  std::vector<std::string> warnings;
};

// The partition's sub-volumes swept. `solid`
// is the partition's volume to remove, `stock` and `part` the shapes it came from. Cancelled when `progress`
// returns false. InputError for bad settings (an engagement outside ]0, 1], an allowance below 0, …).
SweepResult sweep(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part,
                  const TopoDS_Shape& stock, const SweepSettings& settings);

// The sweeps of several regions (an impeller's channels) as one program, linked safely: where all their moves
// keep one tool axis (S1 on every channel), a retract to one plane beyond the stock (normal to the axis,
// `clearance` mm above the stock) and a straight move there; otherwise (S3's own setup per channel, 4 and
// 5 axes) out along the tool axis to a sphere about the stock (its bounding box's, `clearance` mm beyond),
// the axis turned there to point away from the stock's centre, along the sphere (chords within clearance / 2
// of it), the axis turned to the next region's, and in along it. Each tool position of a link then has its
// whole length outside the stock. The regions' own first and last moves are kept.
std::vector<ToolMove> joinSweeps(const std::vector<std::vector<ToolMove>>& regions, const TopoDS_Shape& stock,
                                 double clearance = 5.0);

}  // namespace hsm::roughing
