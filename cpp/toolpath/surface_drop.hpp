// Exact drop of a ball on one smooth face: the ball centre lies on the face's offset surface S + r·n, and
// for a tool at (x, y) Newton finds the (u, v) whose offset point is above (x, y). No mesh, so no mesh
// error on the face being finished; the faces around it are left to the mesh drop-cutter.
#pragma once

#include "geometry/face_drop.hpp"

#include <Geom_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <memory>

namespace hsm::toolpath {

class SurfaceBallDrop {
public:
  // `toolSide`: +1 when the tool is on the side of the surface's natural normal Su × Sv, −1 on the other
  // (toolpath/reach.hpp tells which).
  SurfaceBallDrop(const TopoDS_Face& face, double radius, double toolSide);

  struct Result {
    double tipZ = 0.0;     // tool tip height
    double u = 0.0, v = 0.0;  // contact point parameters
    bool onFace = false;   // the contact point is inside the face's boundaries, and the ball rests on it
                           // from above (where the face looks down, a ball from above cannot touch it)
  };
  // (u, v) in `guess` when `haveGuess`; false when Newton does not converge (no contact on the surface).
  bool drop(double x, double y, Result& result, bool haveGuess) const;
  const Handle(Geom_Surface)& surface() const { return surface_; }
  // (u, v) inside the face's boundaries.
  bool inside(double u, double v) const { return dropper_.inside(u, v); }

private:
  bool newton(double x, double y, double& u, double& v, Eigen::Vector3d& centre) const;

  Handle(Geom_Surface) surface_;
  geometry::FaceDropper dropper_;  // first guesses, and the inside test
  double radius_, sign_;           // sign_: which side of the surface the tool is on
  double u0_, u1_, v0_, v1_;
};

}  // namespace hsm::toolpath
