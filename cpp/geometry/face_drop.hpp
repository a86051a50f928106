// Points dropped on a face along the tool axis: the plan position is kept, the height comes from the face.
#pragma once

#include "geometry/curve_sampling.hpp"

#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <memory>
#include <vector>

class BRepTopAdaptor_FClass2d;

namespace hsm::geometry {

class FaceDropper {
public:
  FaceDropper(const TopoDS_Face& face, const Eigen::Vector3d& axis);
  ~FaceDropper();
  // Moves each point onto the face's surface along the axis (Newton from the previous point's parameters).
  // Returns the number of points that could not be dropped (left where they were): the surface is
  // vertical there, or the line along the axis misses it.
  int drop(PointArray& points) const;
  // As drop(), and tells for each point whether it landed inside the face's boundaries.
  std::vector<char> dropAndClassify(PointArray& points) const;

private:
  bool dropOne(Eigen::Ref<Eigen::RowVector3d> point, double& u, double& v, bool haveGuess) const;

  TopoDS_Face face_;
  Handle(Geom_Surface) surface_;
  Handle(ShapeAnalysis_Surface) analysis_;
  mutable std::unique_ptr<BRepTopAdaptor_FClass2d> classifier_;  // built on first use
  Eigen::Vector3d axis_, e1_, e2_;
  double u0_, u1_, v0_, v1_;
};

}  // namespace hsm::geometry
