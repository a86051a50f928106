// Points along a curve given as an edge or a wire: the common input of curve nets and toolpaths.
#pragma once

#include <Eigen/Geometry>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

namespace hsm::geometry {

// An (N,3) array of points, row-major so that it maps one to one onto a numpy array.
using PointArray = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Turns an edge, a wire or a compound of connected edges into one wire, edges in chain order.
// Throws InputError for a shape with no edge, edges that do not chain, or a chain of zero length.
TopoDS_Wire toWire(const TopoDS_Shape& curve);

// `count` points spaced equally by arc length along the curve, first and last point included.
// Throws InputError when count < 2 or the curve is not a chain of edges of non-zero length.
PointArray sampleByArcLength(const TopoDS_Shape& curve, int count);

}  // namespace hsm::geometry
