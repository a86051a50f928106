// Fuzz harness of curve nets: BREP text whose first two edges are the boundaries and whose first face (if
// any) is the bottom face; the first line gives K, P, the mode (0–4) and the minimum gap.
#include "curvenet/curvenet.hpp"
#include "fuzz_input.hpp"
#include "geometry/brep.hpp"
#include "geometry/bspline.hpp"

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const hsm::fuzz::Input input = hsm::fuzz::split(data, size);
  hsm::fuzz::expectOnlyCoreErrors("fuzz_brep_curvenet", [&] {
    const TopoDS_Shape shape = hsm::geometry::readBrep(input.brep);
    TopTools_IndexedMapOfShape edges, faces;
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    if (edges.Extent() < 2) return;
    hsm::curvenet::Boundaries boundaries{hsm::geometry::toBSpline(edges(1)), hsm::geometry::toBSpline(edges(2))};
    hsm::curvenet::NetSettings settings;
    settings.step = input.number(1, 5.0);  // the core must refuse what is out of range: not clamped here
    settings.minGap = input.number(3, 2.0);
    if (faces.Extent() > 0) settings.face = TopoDS::Face(faces(1));
    const int mode = int(std::clamp(input.number(2, 0.0), 0.0, 4.0));
    const auto net = hsm::curvenet::curveNet(boundaries, input.number(0, 0.5),
                                             static_cast<hsm::curvenet::NetMode>(mode), settings);
    for (const auto& curve : net.curves)
      if (curve.curve.IsNull()) hsm::fuzz::finding("fuzz_brep_curvenet", "a net curve without geometry");
  });
  return 0;
}
