// The machining direction of parallel-plane finishing chosen by directional beams (Quinsat & Sabourin,
// "Optimal selection of machining direction for three-axis milling of sculptured parts", 2006).
//
// At each sample point M of a face (normal n, tool axis k) and for each direction d = (cos θ, sin θ, 0):
//   p1² = (8·Sz·Ro − fz²)·((d×n/|d×n|) × d · k)²                       (eq. 9, the transverse step for Sz)
//   Rc: radius of the tool path, the section of the offset surface S + Ro·n by the vertical plane through
//       d (Meusnier: κ = κn/cos, κn from the offset's principal curvatures κi/(1 − Ro·κi) by Euler)
//   fz = min(Vf, √(Rc·a) [, ∛(J·Rc²)]) / (Z·N)                         (eq. 10–11, real feed per tooth)
//   G_p = p1·fz                                                           (eq. 12)
// A beam Fd(M) = {d : G_p ≥ α·G_pmax(M)} (eq. 15); the beams meet (eq. 16) for every α up to
// α* = max_θ min_M G_p(M, θ)/G_pmax(M), at θ*: the optimal direction. The paper's algorithm (Fig. 8)
// raises α until the intersection empties, halving its step; it converges to α* (tested).
//
// Beyond the paper: the predicted cutting time of parallel planes per direction, T(θ) = Σ A·√(1 + s²)/(p1·Vf)
// with A the plan area a point stands for, s the slope along d, Vf = fz·Z·N the real feed and p1 the
// smallest step along the point's plane (the points within half a spacing across it), plus per plane its
// run-out of a tool radius past each end and the time a stop and a start cost there; and the direction
// minimising it.
//
// The machine: a_max (and J) are those of the slowest of its X and Y axes (kinematics::slowestPlanAxes,
// the paper's a_max for a path in any plan direction); the stop and start at a plane's end take the
// controller's profile (S-curve on an 840D in SOFT, trapezoid on LinuxCNC and grbl).
//
// Where the paper is silent: the tool is on the side of the face's normal as FreeCAD shows it (out of the
// material for a face of a solid); curvatures are signed positive where the face bends towards the tool;
// points whose concave radius is below the ball's, undercut (n·k < 0) or vertical (n·k ≈ 0) are left out
// with a warning (refused if no point is left, and a face that looks down is refused as such); a flat face,
// where every direction ties, is reported as such.
#pragma once

#include "geometry/points.hpp"
#include "kinematics/machine.hpp"
#include "kinematics/physics.hpp"

#include <TopoDS_Face.hxx>

#include <string>
#include <vector>

namespace hsm::direction {

struct CuttingConditions {
  double toolRadius = 5.0;       // Ro, mm (ball end)
  double scallop = 0.01;         // Sz, mm
  double programmedFeed = 100.0; // Vf, mm/s
  double spindleSpeed = 250.0;   // N, rev/s
  int teeth = 2;                 // Z
  bool jerkLimitsFeed = false;   // the real feed also ≤ ∛(J·Rc²) (beyond the paper, whose model has no jerk)

  double programmedFeedPerTooth() const { return programmedFeed / (teeth * spindleSpeed); }
};

struct SurfacePoint {
  Eigen::Vector3d point, normal;          // normal towards the tool (n·k > 0)
  double k1 = 0.0, k2 = 0.0;              // principal curvatures, > 0 where the face bends towards the tool
  Eigen::Vector3d e1, e2;                 // principal directions
  double planArea = 1.0;                  // mm² of the face's plan view the point stands for
};

// Sample points of the face on an nu × nv grid of its parameters, inside its boundaries.
std::vector<SurfacePoint> sampleFace(const TopoDS_Face& face, int nu, int nv);

struct Performance {
  double transverseStep = 0.0;  // p1, mm
  double feedPerTooth = 0.0;    // real fz, mm
  double pathRadius = 0.0;      // Rc, mm (infinity: straight)
  double fitness = 0.0;         // G_p = p1·fz, mm²
};

// Eq. 9–12 at one point for the direction at `thetaDeg` from X; `planAxes`: a_max and J of the machine
// (kinematics::slowestPlanAxes).
Performance performance(const SurfacePoint& m, double thetaDeg, const CuttingConditions& c,
                        const kinematics::Dynamics& planAxes);

// Bounded work: at most kMaxGrid × kMaxGrid points, directions every kMinAngleStepDeg or more, and at
// most kMaxEvaluations point-direction pairs.
inline constexpr int kMaxGrid = 500;
inline constexpr double kMinAngleStepDeg = 0.01;
inline constexpr double kMaxEvaluations = 1e8;

struct DirectionSettings {
  int gridU = 50, gridV = 50;   // sample points
  double angleStepDeg = 1.0;    // directions over [0°, 180°)
  double reportAlpha = 0.95;    // the acceptable set reported is I(min(α*, reportAlpha))
};

struct DirectionResult {
  std::vector<double> anglesDeg;      // directions sampled
  std::vector<double> rate;           // min over the points of G_p/G_pmax, per direction
  double optimalAngleDeg = 0.0;       // θ*
  double alpha = 0.0;                 // α*
  double reportedAlpha = 0.0;         // the α of `acceptableDeg`
  std::vector<double> acceptableDeg;  // directions in I(reportedAlpha)
  geometry::PointArray points;        // the points used
  std::vector<double> bestAngleDeg;   // per point: the direction of G_pmax
  std::vector<double> fitnessMax;     // per point: G_pmax, mm²
  // Beyond the paper: the cutting time the same model predicts for parallel planes over the whole face,
  // per direction, and the direction where it is least. The beams guard the worst point; this weighs every
  // point by the area it stands for, and gives each plane the smallest step along it, as planes have.
  std::vector<double> predictedTime;  // s, per direction (infinite where some point gets no step)
  double fastestAngleDeg = 0.0;
  bool allTie = false;                // flat face: every direction equal
  std::vector<std::string> warnings;
};

DirectionResult optimalDirection(const TopoDS_Face& face, const CuttingConditions& c,
                                 const kinematics::MachineModel& machine, const DirectionSettings& s = {});
DirectionResult optimalDirection(const std::vector<SurfacePoint>& points, const CuttingConditions& c,
                                 const kinematics::MachineModel& machine, const DirectionSettings& s = {});

// The paper's algorithm (Fig. 8) on the rate per direction: α from `start` in steps of `step`, halved each
// time the beams' intersection empties, until the step is below `precision`. Returns the largest α whose
// intersection is not empty.
double beamAlgorithmAlpha(const std::vector<double>& rate, double start = 0.5, double step = 0.1,
                          double precision = 1e-6);

}  // namespace hsm::direction
