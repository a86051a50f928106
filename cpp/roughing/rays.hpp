// Lines against the faces of a shape: where a ray first meets it, and every crossing of a line.
// OCCT's IntCurvesFace_ShapeIntersector does this, but 7.6 frees with `delete` arrays it made with `new[]`
// (AddressSanitizer's alloc-dealloc-mismatch in its destructor): this keeps one IntCurvesFace_Intersector per
// face, behind its bounding box, as that class does inside.
#pragma once

#include <Bnd_Box.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Lin.hxx>

#include <memory>
#include <vector>

namespace hsm::roughing {

struct RayHit {
  double w = 0.0;     // parameter along the line (distance for a unit direction)
  double u = 0.0, v = 0.0;  // on the face's surface
  int face = -1;      // index into RayCaster::faces()
};

class RayCaster {
public:
  RayCaster(const TopoDS_Shape& shape, double tolerance);
  // The crossings of the line within [from, to], sorted by w.
  std::vector<RayHit> all(const gp_Lin& line, double from, double to) const;
  // The first crossing within [from, to]; face -1 when there is none.
  RayHit nearest(const gp_Lin& line, double from, double to) const;
  const std::vector<TopoDS_Face>& faces() const { return faces_; }

private:
  std::vector<TopoDS_Face> faces_;
  std::vector<Bnd_Box> boxes_;
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> intersectors_;
};

}  // namespace hsm::roughing
