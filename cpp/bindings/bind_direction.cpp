#include "bindings/bindings.hpp"

#include "common/error.hpp"
#include "direction/direction.hpp"
#include "geometry/brep.hpp"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace hsm::bindings {

void bindDirection(py::module_& m) {
  using namespace direction;
  py::class_<DirectionResult>(m, "DirectionResult", "The machining direction chosen by directional beams")
      .def_readonly("angles_deg", &DirectionResult::anglesDeg)
      .def_readonly("rate", &DirectionResult::rate, "min over the points of G_p/G_pmax, per direction")
      .def_readonly("angle_deg", &DirectionResult::optimalAngleDeg, "the optimal direction, degrees from X")
      .def_readonly("alpha", &DirectionResult::alpha, "the largest α at which the beams still meet")
      .def_readonly("reported_alpha", &DirectionResult::reportedAlpha)
      .def_readonly("acceptable", &DirectionResult::acceptableDeg, "directions in I(reported_alpha), degrees")
      .def_readonly("points", &DirectionResult::points)
      .def_readonly("best_angle_deg", &DirectionResult::bestAngleDeg, "per point: the direction of G_pmax")
      .def_readonly("fitness_max", &DirectionResult::fitnessMax, "per point: G_pmax, mm²")
      .def_readonly("predicted_time_s", &DirectionResult::predictedTime,
                    "per direction: the cutting time the model predicts for the face, s (beyond the paper)")
      .def_readonly("fastest_angle_deg", &DirectionResult::fastestAngleDeg, "the direction of least predicted time")
      .def_readonly("all_tie", &DirectionResult::allTie)
      .def_readonly("warnings", &DirectionResult::warnings);
  m.def(
      "optimal_direction",
      [](const std::string& faceBrep, double toolRadius, double scallop, double feed, double spindle, int teeth,
         double acceleration, double jerk, double stopJerk, int gridU, int gridV, double angleStep,
         double reportAlpha) {
        CuttingConditions c{toolRadius, scallop, feed, spindle, teeth, acceleration, jerk, stopJerk};
        const DirectionSettings s{gridU, gridV, angleStep, reportAlpha};
        const TopoDS_Face face = geometry::singleFace(geometry::readBrep(faceBrep));
        py::gil_scoped_release release;
        return guarded("machining direction", [&] { return optimalDirection(face, c, s); });
      },
      py::arg("face_brep"), py::arg("tool_radius"), py::arg("scallop"), py::arg("feed"), py::arg("spindle_speed"),
      py::arg("teeth"), py::arg("acceleration"), py::arg("jerk") = 0.0, py::arg("stop_jerk") = 0.0, py::arg("grid_u") = 50,
      py::arg("grid_v") = 50, py::arg("angle_step") = 1.0, py::arg("report_alpha") = 0.95,
      "Directional beams (mm, s: feed in mm/s, spindle speed in rev/s, acceleration in mm/s²)");
  m.def("beam_algorithm_alpha", &beamAlgorithmAlpha, py::arg("rate"), py::arg("start") = 0.5, py::arg("step") = 0.1,
        py::arg("precision") = 1e-6, "The paper's Fig. 8 algorithm on a rate per direction");
}

}  // namespace hsm::bindings
