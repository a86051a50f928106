// Regions of the bottom face between consecutive curves of a net: the elementary machining areas.
#pragma once

#include "curvenet/curvenet.hpp"

#include <TopoDS_Shape.hxx>

#include <vector>

namespace hsm::curvenet {

struct AreaRegion {
  ElementaryArea area;
  TopoDS_Shape faces;  // compound of the pieces of the bottom face between the two curves
  double surfaceArea = 0.0;  // mm²
};

// Splits `face` by the curves of the net (each swept along the tool axis and extended past its ends) and
// gives each piece to the elementary area whose two curves enclose it. Throws ComputationError if OCCT
// cannot split the face.
std::vector<AreaRegion> areaRegions(const CurveNet& net, const TopoDS_Face& face,
                                    const Eigen::Vector3d& toolAxis = Eigen::Vector3d::UnitZ());

}  // namespace hsm::curvenet
