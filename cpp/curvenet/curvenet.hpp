// Curve nets between two boundaries of a bottom feature (guidance-curve paper §3 and §4.3).
//
// Our reading of the paper, and the rules where it is silent (each one is tested):
// - Stations: planes perpendicular to the machining direction d, evenly spaced by at most P over the common
//   extent of the two curves along d, both ends included. The 4-step method adapts the spacing.
// - Points: in each plane Pint = Pa + K·(Pb − Pa), K in ]0,1[ measured from the starting curve Ca. With a
//   bottom face, Pint is then dropped on the face along the tool axis (its plan position is kept), so every
//   curve of the net lies on the face.
// - Curve: a degree-5 B-spline approximating the points within the fit tolerance (0.01 mm by default, the
//   machining tolerance of the paper), chord-length parameters, C2. Interpolating sparse points with degree 5
//   overshoots between them; using them as poles moves the curve off the points by millimetres. Fewer than
//   6 points lower the degree to (points − 1) with a warning.
// - A plane that cuts a curve more than once: the cut that continues the curve is used (the first one, in the
//   curve's own order, after the cut used in the previous plane), with a warning.
// - Boundaries of different extents: the net covers their common extent along d, with a warning giving what
//   is left out. Boundaries that touch or pinch: every curve passes through the contact (eq. 1 of two equal
//   points is that point), and the stop rule ignores the planes where the boundaries are closer than the
//   minimum gap or than a quarter of their largest distance, so that the net still divides the wide part.
//   Boundaries that cross: refused (InputError).
// - Stop rule: a net grows from its starting curve towards a target; a new curve that comes closer than the
//   minimum gap to the target (or reaches its other side) in any plane but the pinches is dropped and the net
//   ends. The
//   default gap, 2 mm, the radius of the paper's 4 mm ball, reproduces the curve counts of Tables 1 and 2.
//
// Bounded work: a net has at most kMaxPlanes planes (a step P that would need more is refused
// with the step that fits), P at least kMinStep, the fit tolerance in [kMinFitTolerance, 1] mm, and at
// most maxCurvesPerNet curves per net: a K that would need more (each curve closes the share K of the
// gap left, so about log(gap/width)/log(1 − K) curves) is refused before any is built. A minimum gap as
// wide as the area is refused (every plane would be a pinch and no net could stop). Boundaries drawn off
// the face (a sketch above it) are put on the face along the tool axis, with a warning, so that the stop
// rule measures on the face. Construction points that fall outside the face (over a hole) are warned of.
#pragma once

#include "common/progress.hpp"
#include "geometry/points.hpp"

#include <Eigen/Geometry>
#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Face.hxx>

#include <optional>
#include <string>
#include <vector>

namespace hsm::curvenet {

using geometry::PointArray;

inline constexpr int kMaxPlanes = 2000;
inline constexpr double kMinStep = 0.01;          // mm
inline constexpr double kMinFitTolerance = 1e-4;  // mm

struct NetSettings {
  double step = 5.0;                          // P, mm: largest distance between two planes
  std::optional<Eigen::Vector3d> direction;   // machining direction; default: mean chord of the boundaries,
                                              // snapped to a machine axis within 10°
  Eigen::Vector3d toolAxis{0.0, 0.0, 1.0};    // planes contain it; points are dropped on the face along it
  std::optional<TopoDS_Face> face;            // bottom face: when set, every curve is put on it
  double fitTolerance = 0.01;                 // mm, B-spline approximation of the points
  double minGap = 2.0;                        // mm, stop rule of the iterative nets
  double pinchFraction = 0.25;                // planes narrower than this share of the widest one are pinches
  int maxCurvesPerNet = 200;                  // a K that would need more curves is refused
  ProgressCallback progress;                  // per curve built; false cancels (throws Cancelled)
};

enum class CurveRole { Boundary, Median, Intermediate };

struct NetCurve {
  CurveRole role = CurveRole::Intermediate;
  std::string label;                 // "B1", "B2", "Cmed", "C1.3" (net 1, third curve built)…
  Handle(Geom_BSplineCurve) curve;   // oriented along +d
  PointArray points;                 // construction points, one per plane (empty for boundaries)
  double k = 0.0;                    // ratio it was built with (0 for boundaries)
  std::string from, towards;         // labels of the starting and target curves
  int net = 0;                       // 1: from/towards the B1 side, 2: the B2 side, 0: boundaries and median
  int rank = 0;                      // order of construction within its net, 1 = first built
  double fitDeviation = 0.0;         // mm, largest distance from a construction point to the curve
};

// An elementary machining area: the region between two consecutive curves of the net.
struct ElementaryArea {
  int lower = 0, upper = 0;  // indices in CurveNet::curves, lower on the B1 side
};

struct CurveNet {
  std::vector<NetCurve> curves;     // across the feature, from B1 to B2, boundaries included
  std::vector<double> stations;     // plane positions along the direction, mm (d·x)
  Eigen::Vector3d direction{1.0, 0.0, 0.0};
  std::vector<std::string> warnings;

  std::vector<ElementaryArea> elementaryAreas() const;
  // Tables 1–2 of the paper: MA_j uses the first j curves built of each net (and the median, if any).
  std::vector<std::vector<ElementaryArea>> composedAreas() const;
};

enum class NetMode {
  B1ToB2,              // C1 between B1 and B2, then C_j between C_{j-1} and B2…
  B2ToB1,
  Median,              // the median only (K is ignored, 0.5)
  MedianToBoundaries,  // the median, then a net from it towards each boundary
  BoundariesToMedian,  // the median, then a net from each boundary towards it
};

// Curves given by the user, as B-splines (see geometry::toBSpline and geometry::interpolatePoints).
struct Boundaries {
  Handle(Geom_BSplineCurve) b1, b2;
};

// One intermediate curve between ca and cb (eq. 1–2), labelled "C".
NetCurve intermediateCurve(const Handle(Geom_BSplineCurve)& ca, const Handle(Geom_BSplineCurve)& cb, double k,
                           const NetSettings& settings);

CurveNet curveNet(const Boundaries& boundaries, double k, NetMode mode, const NetSettings& settings);

// The 4-step method of §4.3, steps 1–3 (step 4, the simulation, is the user's).
struct GuidanceSettings {
  NetSettings net;            // net.step is the initial step P0 (5 mm in the paper)
  double kMedian = 0.5;
  double k = 0.75;
  double minStep = 0.5;       // mm: the adapted step never goes below this
};

struct GuidanceHalf {
  std::string start, target;  // labels: the guide with the larger smallest radius starts
  double startMinRadius = 0.0, targetMinRadius = 0.0;  // mm
  bool skipped = false;       // both guides straight: no curve needed
};

struct GuidanceReport {
  std::vector<double> inflectionStations;   // projections of the guides' inflection points on d, mm
  double smallestStep = 0.0, largestStep = 0.0;  // adapted plane spacing, mm
  GuidanceHalf half1, half2;                // B1 side, B2 side
};

struct GuidanceResult {
  CurveNet net;
  GuidanceReport report;
};

GuidanceResult guidanceCurves(const Boundaries& boundaries, const GuidanceSettings& settings);

// "b1_to_b2", "b2_to_b1", "median", "median_to_boundaries", "boundaries_to_median" (the names Python's
// hsmplanner.NetMode gives them), for messages.
std::string netModeName(NetMode mode);

}  // namespace hsm::curvenet
