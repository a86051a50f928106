// How the sweep (sweep.cpp) lays a slicing surface flat for its 2-D passes (internal to the roughing): plane
// coordinates of a point in Clipper's integers, its height along the tool axis, and back.
//   planes (S1, S3; S4, S5 on planar faces)   as they are, the height along the normal;
//   coaxial cylinders (S2)                    unrolled at the level's radius, (r·θ, z), the tool axis radial;
//   offsets of a surface of revolution (S4, S5)   (ρ_ref·θ, s): the angle about the axis times the largest
//       radius of the level's tip surface, and the arc length along the reference meridian; the height is the
//       signed distance across the meridian (roughing/meridian.hpp), the tool axis the offsets' normal.
// The last is not isometric: a flat millimetre is `scalesAt` true millimetres at a point, one scale along x
// (less towards the axis), one along y (more on the offsets of a convex meridian). The sweep grows the part's
// shadow by its clearance over the scales where the part is, and spaces the passes by the engagement over the largest scale on the level: the
// passes are never farther apart than asked and never nearer the part than the allowance (first order; the
// surface's bending under the tool's disk is `concavity`).
#pragma once

#include "geometry/mesh.hpp"
#include "roughing/roughing.hpp"

#include <Eigen/Core>
#include <polyclipping/clipper.hpp>

#include <limits>
#include <memory>

namespace hsm::roughing {

namespace cl = ClipperLib;
inline constexpr double kScale = 1e4;  // Clipper units per mm: 0.1 µm

class Projection {
public:
  virtual ~Projection() = default;
  virtual double height(const Eigen::Vector3d& p) const = 0;       // NaN where the point has no coordinates
  virtual cl::IntPoint plane(const Eigen::Vector3d& p) const = 0;
  virtual Eigen::Vector3d point(const cl::IntPoint& q, double h) const = 0;
  virtual Eigen::Vector3d axisAt(const Eigen::Vector3d& p) const = 0;  // unit, towards the spindle
  // The axis at the point of plane coordinates q and height h, as axisAt(point(q, h)) but safe from several
  // threads at once (no lookup that remembers).
  virtual Eigen::Vector3d axisAtPlane(const cl::IntPoint& q, double h) const { return axisAt(point(q, h)); }
  // The level whose passes are laid flat next: its tip's height and the slice's mesh.
  virtual void setLevel(double tipHeight, const geometry::TriangleMesh& slice) { (void)tipHeight, (void)slice; }
  // Longest straight move between two points of the flat passes that stays within `tolerance` of the surface
  // at height h (∞ on planes).
  virtual double maxSegment(double h, double tolerance) const {
    (void)h, (void)tolerance;
    return std::numeric_limits<double>::infinity();
  }
  // Whether the straight edge a–b, laid flat, bows off its image's chord (it is then laid flat in halves);
  // whether a triangle cannot be laid flat.
  virtual bool bends(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    (void)a, (void)b;
    return false;
  }
  virtual bool skip(const Eigen::Vector3d (&p)[3]) const {
    (void)p;
    return false;
  }
  virtual bool cullsBackFaces() const { return false; }
  // True mm per flat mm at a point, at its own height, along the plane's x and y (≥ 1 on planes and on
  // cylinders above the tip), and the largest and least over the level's tip surface.
  virtual Eigen::Vector2d scalesAt(const Eigen::Vector3d& p) const {
    (void)p;
    return {1.0, 1.0};
  }
  virtual double largestScale() const { return 1.0; }
  virtual double smallestScale() const { return 1.0; }
  // How far (1/mm) the level's tip surface curves up towards the tool: a disk of radius r on it has its rim
  // r²·concavity/2 nearer the surface than its centre.
  virtual double concavity() const { return 0.0; }
  // The same across the plane's x alone (at most `concavity`): round the axis of a surface of revolution the
  // level may fall away while its meridian curves up.
  virtual double concavityAcross() const { return concavity(); }
  // How fast (1/mm) the surface through p falls away from the tool across the plane's x, the least over the
  // tool's lines within the reach: a point D true mm beside a tool's line round the axis of a surface of
  // revolution stands at least D²·convexity/2 lower along that line than its own height (the line leans out
  // from the axis by its radial share n_r, the point turned about the axis falls by ρ(1 − cos θ)·n_r). 0 on
  // planes, and wherever the lines lean in. The greatest over the level's tip surface is `convexity`.
  virtual double convexityAt(const Eigen::Vector3d& p) const {
    (void)p;
    return 0.0;
  }
  virtual double convexity() const { return 0.0; }
  // The farthest (true mm) the sweep keeps the part from the tool's axis: scales that hold only nearby (the
  // angle round a cylinder's axis against its sine) are taken on the safe side over that distance.
  void setReach(double mm) { reach_ = mm; }

protected:
  double reach_ = 0.0;
};

// The projection of a partition's slicing surfaces. InputError for surfaces the sweep does not lay flat (a
// free-form reference face that is not a surface of revolution, a bore's cylinders).
std::unique_ptr<Projection> projectionOf(const Partition& partition, const RemovalSolid& solid);

}  // namespace hsm::roughing
