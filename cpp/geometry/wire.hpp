// A curve given as an edge, a wire or a compound of connected edges, as one wire: the common input of curve
// nets and toolpaths. (B-splines of it, and points along it: geometry/bspline.hpp.)
#pragma once

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace hsm::geometry {

// Turns an edge, a wire or a compound of connected edges into one wire, edges in chain order.
// Throws InputError for a shape with no edge, edges that do not chain, or a chain of zero length.
TopoDS_Wire toWire(const TopoDS_Shape& curve);

}  // namespace hsm::geometry
