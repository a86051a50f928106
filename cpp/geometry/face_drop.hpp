// Points dropped on a face along the tool axis: the plan position is kept, the height comes from the face.
#pragma once

#include "geometry/points.hpp"

#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <memory>
#include <vector>

namespace hsm::geometry {

// Point-in-face test in the face's (u, v) parameters: its boundary edges sampled as segments (400 per
// edge), sorted into bands of v, and an even-odd ray count over the segments of one band. OCCT's
// BRepTopAdaptor_FClass2d tests every boundary point and was most of a toolpath's time.
class UVClassifier {
public:
  explicit UVClassifier(const TopoDS_Face& face);
  bool inside(double u, double v) const;

private:
  struct Segment {
    double u0, v0, u1, v1;
  };
  std::vector<Segment> segments_;
  std::vector<std::vector<int>> bands_;
  double vMin_ = 0.0, bandHeight_ = 1.0;
};

// A first guess of the (u, v) above a plan position: the surface sampled on a 128 × 128 grid of its
// parameters, the samples splatted into a grid of plan cells. Replaces OCCT's point projection
// (Extrema_GenExtPS) as the start of Newton: O(1) instead of a search over the whole surface.
class UVLocator {
public:
  UVLocator(const Handle(Geom_Surface)& surface, double u0, double u1, double v0, double v1);
  // false when (x, y) is outside the plan area the surface covers.
  bool guess(double x, double y, double& u, double& v) const;

private:
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<float> u_, v_;  // per cell; NaN where no sample fell
};

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
  // One point: moved onto the surface (true) or left (false); (u, v) in: the guess when `haveGuess`, out:
  // the surface parameters found.
  bool dropOne(Eigen::Ref<Eigen::RowVector3d> point, double& u, double& v, bool haveGuess) const;
  bool inside(double u, double v) const;
  const Handle(Geom_Surface)& surface() const { return surface_; }

private:
  bool newton(Eigen::Ref<Eigen::RowVector3d> point, double& u, double& v) const;

  TopoDS_Face face_;
  Handle(Geom_Surface) surface_;
  Handle(ShapeAnalysis_Surface) analysis_;
  std::unique_ptr<UVLocator> locator_;
  mutable std::unique_ptr<UVClassifier> classifier_;  // built on first use
  Eigen::Vector3d axis_, e1_, e2_;
  double u0_, u1_, v0_, v1_;
};

}  // namespace hsm::geometry
