// 3-axis ball-end finishing of a bottom face: parallel planes, and passes morphed between guide curves
// (guidance-curve paper §2.2, §3).
//
// How (where the paper is silent, the choices are ours, as a CAM programmer expects them):
// - Gouge-free positions: the ball dropped exactly on the bottom face (its centre on the offset surface,
//   found by Newton: no mesh error where the finish matters) and by drop-cutter on a mesh of every face
//   touching it (flanks, within 0.004 mm) and on the bottom face's own edges; the highest contact wins.
//   Positions are of the tool tip.
// - Stepover: the next pass is the farthest one that leaves at most the cusp height on the real face at
//   every station of the current pass: in the plane normal to the path of the ball's centre, the ridge
//   where that ball's circle meets the next pass's balls, its height above the face (toolpath/cusp.hpp).
//   Passes close up on convex parts and open on concave ones; where the contacts slide along the pass
//   from one pass to the next (valleys crossed at a slant, morphed passes) they are not crowded. Where the
//   current pass is off the face, the next steps by at most the flat-face stepover 2·sqrt(2·r·h − h²).
// - Points: the cutter positions are sampled, refined where the path bends, then reduced to the fewest
//   G1 points within the machining tolerance (Douglas–Peucker on the refined polyline).
// - Passes keep the ball on the bottom face: where a flank would hold it up the pass ends (the first pass
//   along a wall is the one whose ball touches both wall and bottom; the fillet of the tool's radius is
//   left, as by any ball); past an open boundary (where nothing lifts the tool) a pass goes on by the
//   extension (the tool radius by default) so that the ball leaves the face whole.
// - Sweeping: upward orders the passes so that the stepover climbs (the first pass is on the lower side),
//   downward the other way. Zigzag alternates pass directions and links neighbours by a G1 move that
//   follows the surface when they are within ten tool radii and the link would not climb a wall;
//   otherwise, and for one-way, the tool retracts to the safe height, moves in G0 and plunges in G1.
// - Reach: the drop-cutter holds the tool off every face of the part, not only the bottom
//   face's neighbours, so no pass can cut through the part to a face below. A face the tool along +Z
//   cannot reach (a wall, a face that looks down) is refused by name; where only part of it is out of
//   reach, that part is left with a warning (toolpath/reach.hpp).
// - Holes in the bottom face: where a pass crosses a hole (the face is missing and nothing stands above
//   the straight line between the hole's rims) no wider than ten tool radii along the pass, the tool
//   bridges it at the face's level in one straight move; the ball does not dip into the hole and the pass
//   goes on without a retract. Wider holes are open edges, as the face's outer open boundaries: the pass
//   rolls over the rim by the extension and links or retracts.
// - Bounded work: the settings are checked against what a finishing computation can do (the limits below);
//   the passes and the points the settings would need are estimated from the face before any is computed,
//   and refused past the limits with the value that would fit. `progress` reports and can cancel.
#pragma once

#include "common/progress.hpp"
#include "geometry/mesh.hpp"
#include "toolpath/dropcutter.hpp"

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace hsm::toolpath {

enum class Sweep { Upward, Downward };

// Limits of the settings (mm), and of the work they may ask for.
inline constexpr double kMinToolRadius = 0.05, kMaxToolRadius = 50.0;
inline constexpr double kMinCuspHeight = 1e-4;     // 0.1 µm: below any machine's repeatability
inline constexpr double kMinTolerance = 1e-4, kMaxTolerance = 1.0;
inline constexpr double kMinSampling = 0.01;       // and at most the tool radius
inline constexpr double kMaxClearance = 1000.0;
inline constexpr long kMaxPasses = 10000;           // estimated from the face's width and the flat stepover
inline constexpr double kMaxPlanPoints = 2e7;       // cutter positions of all passes together

struct FinishingSettings {
  double toolRadius = 2.0;      // ball radius, mm
  double cuspHeight = 0.01;     // mm
  double tolerance = 0.01;      // mm, chordal, for the G1 points
  bool zigzag = true;
  Sweep sweep = Sweep::Upward;
  double clearance = 5.0;       // mm: rapids at the part's top + clearance
  double extension = -1.0;      // mm past open boundaries; < 0: the tool radius
  double meshDeflection = 0.004;  // mm, for the faces around the bottom face
  double meshSeconds = geometry::kMeshSeconds;  // s OCCT's mesher may take on them (a malformed face: for ever)
  double sampling = 0.25;       // mm between cutter positions before refinement
  int threads = 0;              // 0: all cores
  ProgressCallback progress;    // share of the passes done; returning false cancels (throws Cancelled)
};

struct Move {
  Eigen::Vector3d point;
  bool rapid = false;
};

struct Toolpath {
  std::vector<Move> moves;
  int passes = 0;
  std::vector<double> passLengths;  // mm, each pass (piece) as cut, in order
  long droppedPoints = 0;  // cutter positions computed by drop-cutter
  double safeHeight = 0.0;
  std::vector<std::string> warnings;
};

// Refuses settings outside the limits above (InputError names the setting, its range and a usual value):
// what every strategy checks first, for callers that check before they start many (a strategy study).
void checkFinishingSettings(const FinishingSettings& settings);

// Planes containing the tool axis at `angleDeg` from X across the bottom face `bottomFace` (FreeCAD's
// 1-based number in `part`).
Toolpath parallelPlaneFinishing(const TopoDS_Shape& part, int bottomFace, double angleDeg,
                                const FinishingSettings& settings);

// An area between two guide curves; passes are morphed from `first` to `second`.
struct GuideArea {
  Handle(Geom_BSplineCurve) first, second;
};

// Each area machined by passes morphed between its guides, in the order given (a pass on a guide shared
// by two areas is cut once). `direction`: the machining direction the guides' points correspond along.
Toolpath guideCurveFinishing(const TopoDS_Shape& part, int bottomFace, const std::vector<GuideArea>& areas,
                             const Eigen::Vector3d& direction, const FinishingSettings& settings);

}  // namespace hsm::toolpath
