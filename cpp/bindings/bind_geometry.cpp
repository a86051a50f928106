#include "bindings/bindings.hpp"

#include "geometry/brep.hpp"
#include "geometry/bspline.hpp"
#include "geometry/face_drop.hpp"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <array>

namespace py = pybind11;

namespace hsm::bindings {

void bindGeometry(py::module_& module) {
  using geometry::ShapeSummary;
  py::class_<ShapeSummary>(module, "ShapeSummary", "Topology counts and measures of a BREP shape")
      .def_readonly("solids", &ShapeSummary::solids)
      .def_readonly("shells", &ShapeSummary::shells)
      .def_readonly("faces", &ShapeSummary::faces)
      .def_readonly("wires", &ShapeSummary::wires)
      .def_readonly("edges", &ShapeSummary::edges)
      .def_readonly("vertices", &ShapeSummary::vertices)
      .def_readonly("volume", &ShapeSummary::volume, "mm^3")
      .def_readonly("area", &ShapeSummary::area, "mm^2")
      .def_readonly("length", &ShapeSummary::length, "total edge length, mm")
      .def_readonly("valid", &ShapeSummary::valid)
      .def_property_readonly(
          "bounds",
          [](const ShapeSummary& s) -> py::object {
            if (s.bounds.isEmpty()) return py::none();
            const auto& lo = s.bounds.min();
            const auto& hi = s.bounds.max();
            return py::cast(std::array<double, 6>{lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()});
          },
          "(xmin, ymin, zmin, xmax, ymax, zmax) in mm, None for an empty shape");

  module.def(
      "summarize_brep",
      [](const std::string& brep) { return guarded("shape summary", [&] { return geometry::summarize(geometry::readBrep(brep)); }); },
      py::arg("brep"), "Topology counts, volume, area, length, bounds and validity of a BREP shape");
  module.def(
      "sample_curve_brep",
      [](const std::string& brep, int count) { return geometry::sampleByArcLength(geometry::readBrep(brep), count); },
      py::arg("brep"), py::arg("count"),
      "(count, 3) points equally spaced by arc length along an edge, a wire or a chain of edges");
  module.def(
      "drop_on_face",
      [](const std::string& faceBrep, geometry::PointArray points, const Eigen::Vector3d& axis) {
        const geometry::FaceDropper dropper(geometry::singleFace(geometry::readBrep(faceBrep)), axis);
        const std::vector<char> inside = dropper.dropAndClassify(points);
        return std::make_pair(points, std::vector<bool>(inside.begin(), inside.end()));
      },
      py::arg("face_brep"), py::arg("points"), py::arg("axis") = Eigen::Vector3d::UnitZ(),
      "Points moved onto the face along the axis, and whether each landed inside the face");
}

}  // namespace hsm::bindings
