// Fuzz harness of ball-end finishing: BREP text of a part; the first line gives the bottom face number, the
// tool diameter, the cusp height and the angle of the planes. Moves must be finite.
#include "fuzz_input.hpp"
#include "geometry/brep.hpp"
#include "toolpath/finishing.hpp"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const hsm::fuzz::Input input = hsm::fuzz::split(data, size);
  hsm::fuzz::expectOnlyCoreErrors("fuzz_brep_finishing", [&] {
    const TopoDS_Shape part = hsm::geometry::readBrep(input.brep);
    hsm::toolpath::FinishingSettings settings;
    settings.toolRadius = 0.5 * input.number(1, 4.0);
    settings.cuspHeight = input.number(2, 0.05);
    settings.threads = 1;
    settings.meshSeconds = 5.0;  // OCCT 7.9 meshes one corpus input's malformed face for ever: stopped, refused
    const double face = input.number(0, 1.0);
    if (!(std::abs(face) < 1e6)) return;  // the face number is an int in the API
    const auto path = hsm::toolpath::parallelPlaneFinishing(part, int(face), input.number(3, 0.0), settings);
    for (const auto& move : path.moves)
      if (!move.point.allFinite()) hsm::fuzz::finding("fuzz_brep_finishing", "a move that is not finite");
  });
  return 0;
}
