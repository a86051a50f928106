// The master bottom feature of tests/data (written by scripts/make_test_data.py) for C++ tests and benchmarks.
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace hsm::test {

struct MasterFeature {
  TopoDS_Shape shape;
  TopoDS_Face bottom;
  Handle(Geom_BSplineCurve) boundary1, boundary2;
};

// Loads tests/data/master_bottom_feature.{brep,json}; names like "Face4" count as FreeCAD does.
MasterFeature loadMasterFeature();

// The same, loaded once per program.
const MasterFeature& masterFeature();

}  // namespace hsm::test
