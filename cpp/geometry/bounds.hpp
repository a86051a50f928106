#pragma once
// The exact bounds of a shape, from its geometry alone.
//
// OCCT's BRepBndLib::Add reads a face's triangulation when it has one, and the geometry's (looser) control
// points when it has none, so the same part gives other boxes — and other retract heights, grids and mesh
// sizes — after FreeCAD's 3D view or an earlier mesh has triangulated it. Every box the core derives a
// height or a size from comes from here instead.
#include <Bnd_Box.hxx>
#include <TopoDS_Shape.hxx>

namespace hsm::geometry {

// The tight box of the shape's surfaces and edges (triangulations and tolerances ignored); void if empty.
Bnd_Box exactBounds(const TopoDS_Shape& shape);

}  // namespace hsm::geometry
