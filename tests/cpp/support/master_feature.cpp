#include "master_feature.hpp"

#include "geometry/brep.hpp"
#include "geometry/bspline.hpp"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hsm::test {

namespace {
std::string readFile(const std::string& path) {
  std::ifstream stream(path);
  if (!stream) throw std::runtime_error("cannot read " + path + ": run from the build tree of the repository");
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

// FreeCAD's "Face4"/"Edge13": 1-based index in TopExp::MapShapes order.
TopoDS_Shape element(const TopoDS_Shape& shape, const std::string& name) {
  const bool face = name.rfind("Face", 0) == 0;
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, face ? TopAbs_FACE : TopAbs_EDGE, map);
  return map(std::stoi(name.substr(4)));
}
}  // namespace

MasterFeature loadMasterFeature() {
  const std::string base = std::string(HSM_TEST_DATA_DIR) + "/master_bottom_feature";
  const auto names = nlohmann::json::parse(readFile(base + ".json"));
  MasterFeature feature;
  feature.shape = geometry::readBrep(readFile(base + ".brep"));
  feature.bottom = TopoDS::Face(element(feature.shape, names["bottom_face"]));
  feature.boundary1 = geometry::toBSpline(element(feature.shape, names["boundary_1"]));
  feature.boundary2 = geometry::toBSpline(element(feature.shape, names["boundary_2"]));
  return feature;
}

const MasterFeature& masterFeature() {
  static const MasterFeature loaded = loadMasterFeature();
  return loaded;
}

}  // namespace hsm::test
