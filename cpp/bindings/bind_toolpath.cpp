#include "bindings/bindings.hpp"

#include "common/error.hpp"
#include "geometry/brep.hpp"
#include "toolpath/finishing.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace hsm::bindings {

namespace {
using namespace toolpath;

py::tuple output(const Toolpath& path) {
  py::array_t<double> moves({static_cast<py::ssize_t>(path.moves.size()), py::ssize_t(4)});
  auto m = moves.mutable_unchecked<2>();
  for (size_t i = 0; i < path.moves.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    for (int c = 0; c < 3; ++c) m(k, c) = path.moves[i].point[c];
    m(k, 3) = path.moves[i].rapid ? 1.0 : 0.0;
  }
  py::dict stats;
  stats["passes"] = path.passes;
  stats["pass_lengths"] = path.passLengths;
  stats["dropped_points"] = path.droppedPoints;
  stats["safe_height"] = path.safeHeight;
  stats["warnings"] = path.warnings;
  return py::make_tuple(moves, stats);
}
}  // namespace

void bindToolpath(py::module_& m) {
  py::enum_<Sweep>(m, "Sweep", "Passes climb or descend the face")
      .value("upward", Sweep::Upward)
      .value("downward", Sweep::Downward);
  py::class_<FinishingSettings>(m, "FinishingSettings", "Ball-end finishing (mm); progress is given apart")
      .def(py::init<>())
      .def_readwrite("tool_radius", &FinishingSettings::toolRadius, "ball radius, mm")
      .def_readwrite("cusp_height", &FinishingSettings::cuspHeight, "mm")
      .def_readwrite("tolerance", &FinishingSettings::tolerance, "mm, chordal, for the G1 points")
      .def_readwrite("zigzag", &FinishingSettings::zigzag)
      .def_readwrite("sweep", &FinishingSettings::sweep)
      .def_readwrite("clearance", &FinishingSettings::clearance, "mm above the part's top for rapids")
      .def_readwrite("extension", &FinishingSettings::extension, "mm past open boundaries; < 0: the tool radius")
      .def_readwrite("mesh_deflection", &FinishingSettings::meshDeflection, "mm")
      .def_readwrite("sampling", &FinishingSettings::sampling, "mm between cutter positions before refinement")
      .def_readwrite("threads", &FinishingSettings::threads, "0: all cores");
  m.def("check_finishing_settings", &checkFinishingSettings, py::arg("settings"),
        "ValueError naming a finishing setting outside its limits (what every finishing checks first)");
  m.def(
      "parallel_finishing",
      [](const std::string& part, int bottomFace, double angle, FinishingSettings s, const py::object& progress) {
        s.progress = progressCallback(progress);
        const TopoDS_Shape shape = geometry::readBrep(part);
        Toolpath path;
        {
          py::gil_scoped_release release;
          path = guarded("parallel-plane finishing", [&] { return parallelPlaneFinishing(shape, bottomFace, angle, s); });
        }
        return output(path);
      },
      py::arg("part_brep"), py::arg("bottom_face"), py::arg("angle_deg"), py::arg("settings"),
      py::arg("progress") = py::none(),
      "Parallel-plane ball-end finishing: (moves (N,4) x, y, z, rapid flag; stats dict)");
  m.def(
      "guide_finishing",
      [](const std::string& part, int bottomFace, const std::vector<std::pair<BSplineCurve, BSplineCurve>>& areas,
         const Eigen::Vector3d& direction, FinishingSettings s, const py::object& progress) {
        s.progress = progressCallback(progress);
        const TopoDS_Shape shape = geometry::readBrep(part);
        std::vector<GuideArea> guides;
        for (const auto& [a, b] : areas) guides.push_back({a.curve, b.curve});
        Toolpath path;
        {
          py::gil_scoped_release release;
          path = guarded("guide-curve finishing", [&] { return guideCurveFinishing(shape, bottomFace, guides, direction, s); });
        }
        return output(path);
      },
      py::arg("part_brep"), py::arg("bottom_face"), py::arg("areas"), py::arg("direction"), py::arg("settings"),
      py::arg("progress") = py::none(),
      "Guide-curve finishing, areas as (first, second) curve pairs: (moves (N,4), stats dict)");
}

}  // namespace hsm::bindings
