// The families of slicing surfaces of the partition (internal): a depth over space, and the surface of each
// depth as a face large enough to cross the whole volume.
#pragma once

#include "roughing/roughing.hpp"

#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include <memory>
#include <utility>
#include <vector>

namespace hsm::roughing {

class SlicingFamily {
public:
  virtual ~SlicingFamily() = default;
  // Depth of a point: distance from the reference surface, growing into the volume.
  virtual double depth(const gp_Pnt& point) const = 0;
  // The surface at `depth`, as a face beyond the volume in every direction.
  virtual TopoDS_Shape surfaceAt(double depth) const = 0;
  virtual SlicingSurface surfaceDescription(double depth, int referenceFace) const = 0;
  // The surface's unit normal towards the reference surface (out of the volume when the reference is
  // crossable; the partition turns it for S5) at sample points of the surface at `depth` within the slice.
  virtual void axisField(const TopoDS_Shape& slice, double depth, std::vector<Eigen::Vector3d>& points,
                         std::vector<Eigen::Vector3d>& directions) const;

  // The gradient of the depth at p (central differences h apart unless the family knows it exactly).
  virtual Eigen::Vector3d depthGradient(const Eigen::Vector3d& p, double h) const;

  // The partition's work estimate, in seconds of OCCT's splitter on a 2-core machine of 2026: per surface and
  // face of the volume it may cross, and per pair of the family's surfaces (which the splitter intersects with
  // each other too: nothing for parallel planes or concentric analytic surfaces, but nested B-spline offsets
  // make the time grow with the square of their number).
  virtual double crossingCost() const { return 0.02; }
  virtual double pairCost() const { return 0.0; }

  // Least and largest depth over the solid (its mesh nodes, within a fine deflection).
  std::pair<double, double> depthRange(const TopoDS_Shape& solid) const;
};

// Planes normal to `normal` (depth along it).
std::unique_ptr<SlicingFamily> planesAlong(const TopoDS_Shape& solid, const Eigen::Vector3d& normal);
// The family of a strategy following the reference face of the solid (S1, S2, S4, S5).
std::unique_ptr<SlicingFamily> familyOf(const TopoDS_Shape& solid, const TopoDS_Face& reference, Strategy strategy);

// The face's normal into the solid it bounds at the middle of its parameter box, and that point.
Eigen::Vector3d inwardNormalAtCentre(const TopoDS_Face& face, Eigen::Vector3d& point);


}  // namespace hsm::roughing
