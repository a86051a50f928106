// 5-axis roughing by partition of the volume to remove (Jousselin, Quinsat, Tournier, "Méthodologie pour la
// génération d'opérations d'ébauche 5 axes", MUGV 2018, §3), part 1: the volume, its faces, its partition.
//
// The method works on the volume to remove, not on the part. stock − part gives one solid per region (one per
// inter-blade channel on an impeller). Each face of it is classed by where it comes from (the boolean's
// history) and what it sees:
//   crossable         a face of the stock skin: the tool may pass through it (it is air, or material that goes);
//   facing_crossable  a face of the part that sees a crossable face along its normal into the volume (the hub,
//                     a slot's floor): a slicing surface may follow it, the tool comes from the face it sees;
//   not_crossable     any other face of the part (blade sides, slot walls).
// The volume is then cut into sub-volumes by one of five families of slicing surfaces, each swept later with
// the tool axis normal to its surface:
//   S1 planes parallel to a planar crossable face (3 axes);
//   S2 cylinders coaxial with a cylindrical crossable face (4 axes);
//   S3 planes normal to a computed setup direction: the fixed tool axis from which a straight tool reaches
//      the most of the volume without crossing the part (3+2 axes, after Heo et al. 2008);
//   S4 offsets of the stock skin (the crossable faces that are neither S1's plane nor S2's cylinder);
//   S5 offsets of the facing_crossable face (the hub) — S4 and S5 are continuous 5-axis slicings.
// Slices are `step` apart (the axial engagement, default 8 mm: 100 % of the paper's Ø8 r1 torus), from the
// reference surface into the volume.
//
// Where the paper is silent (our choices):
// - a face of the part is facing_crossable when it is vis-à-vis a crossable face: of the rays along its normal
//   from a 5 × 5 grid of points on it, more than half first meet a crossable face across the volume (not one it
//   shares an edge with: a blade side opening onto the skin sees the skin past their common edge, it does not
//   face it) whose normal is within 45° of opposite to the ray (the hub sees the blank's skin head-on; the
//   slot's floor its mouth, 30° off);
// - S1 takes the planar crossable face of largest area; S2 the cylindrical one of largest area; S4 the
//   largest crossable face that is neither; S5 the largest facing_crossable face;
// - offsets of surfaces of revolution are revolved offsets of their meridian (exact); other surfaces are
//   offset by OCCT (BRepOffsetAPI_MakeOffsetShape) and extended beyond the volume;
// - the setup direction of S3 is searched over the hemisphere about the mean outward normal of the crossable
//   faces, coarse to fine: every 16°, plus seeds (each crossable face's normal, each facing_crossable face's
//   normal into the volume: a floor is best reached square to it), then cones about the best four so far with
//   the spacing halved down to `setupResolutionDeg` (default 5°); points of the volume on a grid of
//   `setupGrid` (default 2 mm); a point is reachable along d when nothing of the part lies above it along d
//   (a height map of the part's mesh in the plane normal to d, cells of the grid's size); the direction
//   reaching the most points wins (ties: nearest the mean, the least tilt).
#pragma once

#include "common/progress.hpp"

#include <Eigen/Core>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include <string>
#include <vector>

namespace hsm::roughing {

enum class FaceClass { Crossable, FacingCrossable, NotCrossable };
std::string faceClassName(FaceClass faceClass);

enum class SurfaceKind { Plane, Cylinder, Revolution, Other };

// One solid of the volume to remove, its faces (TopExp order: Face1, Face2…) and their classes. The paper's
// faces are surfaces: B-rep faces of one surface (split by a periodic surface's seam, say) form one group and
// share its class; a channel of the impeller has the paper's 6 groups.
struct RemovalSolid {
  TopoDS_Solid solid;
  double volume = 0.0;                     // mm³
  std::vector<FaceClass> faceClasses;      // per face
  std::vector<SurfaceKind> faceKinds;      // per face
  std::vector<double> faceAreas;           // mm², per face
  std::vector<int> faceGroups;             // per face: its surface's group, 0, 1, … in order of first face
  int groupCount() const;
  double groupArea(int group) const;
};

struct VolumeToRemove {
  std::vector<RemovalSolid> solids;        // one per region, largest first
  double stockVolume = 0.0, partVolume = 0.0, volume = 0.0;  // mm³; volume = Σ solids = stock − part
  bool fuzzyRetry = false;                 // the plain boolean failed its checks and the fuzzy one passed
  std::vector<std::string> warnings;
};

// Bounded work and the relative tolerance every boolean's volumes are checked against.
inline constexpr double kVolumeTolerance = 1e-6;
inline constexpr double kFuzzyValue = 1e-5;     // mm, the retry's fuzzy value
inline constexpr int kMaxSlices = 2000;
// A partition's estimated work, in seconds of OCCT's splitter on a 2-core machine of 2026 (from the number of
// slicing surfaces, the volume's faces and the kind of surface): beyond it the step that fits is offered.
inline constexpr double kMaxPartitionSeconds = 60.0;

// stock − part. InputError for a part or stock that is not a closed valid solid, a stock that does not contain
// the part, nothing to remove; ComputationError when the boolean fails (also silently: volumes that do not add
// up, an invalid result) even with a fuzzy value. Cancelled when `progress` returns false.
VolumeToRemove volumeToRemove(const TopoDS_Shape& stock, const TopoDS_Shape& part, const ProgressCallback& progress = {});

// What is wrong with a boolean's result that should be solids of `expected` mm³ (no solid, invalid, another
// volume: a cut that fails silently returns its input), or empty when nothing is: every boolean's check.
std::string cutProblem(const TopoDS_Shape& result, double expected);

enum class Strategy {
  PlanesParallelToFace = 1,   // S1
  CoaxialCylinders = 2,       // S2
  SetupPlanes = 3,            // S3
  StockOffsets = 4,           // S4
  HubOffsets = 5,             // S5
};
std::string strategyName(Strategy strategy);

// Stock a previous operation left, for rest roughing: points of it `spacing` mm apart (each stands for a cube
// of that side), farther from the part than the allowance. Empty: the whole volume is to be cut.
struct RestStock {
  std::vector<Eigen::Vector3d> points;
  double spacing = 0.0;
};

struct PartitionSettings {
  double step = 8.0;                    // mm between slicing surfaces (axial engagement)
  double setupResolutionDeg = 5.0;      // S3: directions searched every … degrees
  double setupGrid = 2.0;               // S3: spacing of the points of the volume, mm
  int threads = 0;                      // S3's search: threads (0: all cores)
  RestStock rest;                       // S3: the direction that reaches the most of this stock (rest roughing)
                                        // that lies in the volume, instead of the whole volume
  ProgressCallback progress;
};

// The slicing surface a sub-volume lies on (its lower side, the one towards the reference face's far side),
// as the sweeping of part 2 needs it: a plane (origin, normal), a cylinder (axis point, axis direction,
// radius) or an offset of a reference face (its index in the solid and the offset distance).
struct SlicingSurface {
  SurfaceKind kind = SurfaceKind::Plane;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // plane normal, or cylinder axis
  double radius = 0.0;                                    // cylinder
  int referenceFace = 0;                                  // 1-based face of the solid the offsets follow
  double offset = 0.0;                                    // mm from the reference surface
};

struct SubVolume {
  TopoDS_Shape shape;      // a solid (or a compound of the solids of one slice)
  double volume = 0.0;     // mm³
  int slice = 0;           // 0 at the reference surface, then inwards
  SlicingSurface surface;  // the surface at the slice's start
  // The tool axis on the surface: constant for planes (the normal), radial for cylinders, the surface normal
  // for offsets — unit vectors towards the spindle (out through the crossable reference face for S1, S2, S4,
  // away from the floor for S5, along the setup direction for S3) at sample points of the slice's surface.
  std::vector<Eigen::Vector3d> axisPoints, axisDirections;
};

struct Partition {
  Strategy strategy = Strategy::PlanesParallelToFace;
  double step = 0.0;
  int referenceFace = 0;                 // 1-based face of the solid the slicing follows (0 for S3)
  Eigen::Vector3d setupDirection = Eigen::Vector3d::UnitZ();  // S3: the tool axis (reachable share below)
  double setupReach = 0.0;               // S3: share of the volume a straight tool along it reaches
  std::vector<SubVolume> subVolumes;     // in slicing order
  double volume = 0.0;                   // Σ sub-volumes
  std::vector<std::string> warnings;
};

// The solid cut into sub-volumes by the strategy's surfaces. InputError for a step ≤ 0 or larger than the
// volume, a strategy whose reference face does not exist on this solid (S1 without a planar crossable face,
// S2 without a cylindrical one, S5 without a facing_crossable face), too many slices (kMaxSlices) or too much
// work (kMaxPartitionSeconds), each naming the step that fits; ComputationError when OCCT's split is invalid or
// leaves a surface uncut. Cancelled when the progress callback says stop.
Partition partition(const RemovalSolid& solid, const TopoDS_Shape& part, Strategy strategy,
                    const PartitionSettings& settings = {});

// Share (0..1) of the solid's grid points that a straight tool along `direction` (pointing out, towards the
// spindle) reaches without crossing the part.
double reachableShare(const RemovalSolid& solid, const TopoDS_Shape& part, const Eigen::Vector3d& direction,
                      const PartitionSettings& settings = {});

// The direction (unit) from which a straight tool reaches the most of the solid without crossing the part,
// and that share (0..1): S3's setup direction.
std::pair<Eigen::Vector3d, double> setupDirection(const RemovalSolid& solid, const TopoDS_Shape& part,
                                                  const PartitionSettings& settings = {});

}  // namespace hsm::roughing
