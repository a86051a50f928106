#include "geometry/bounds.hpp"

#include <BRepBndLib.hxx>

namespace hsm::geometry {

Bnd_Box exactBounds(const TopoDS_Shape& shape) {
  Bnd_Box box;
  if (!shape.IsNull()) BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  return box;
}

}  // namespace hsm::geometry
