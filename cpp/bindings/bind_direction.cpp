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
  py::class_<CuttingConditions>(m, "CuttingConditions", "Tool and feed of parallel-plane finishing (mm, s)")
      .def(py::init<>())
      .def_readwrite("tool_radius", &CuttingConditions::toolRadius, "Ro, mm (ball end)")
      .def_readwrite("scallop", &CuttingConditions::scallop, "Sz, mm")
      .def_readwrite("programmed_feed", &CuttingConditions::programmedFeed, "Vf, mm/s")
      .def_readwrite("spindle_speed", &CuttingConditions::spindleSpeed, "N, rev/s")
      .def_readwrite("teeth", &CuttingConditions::teeth, "Z")
      .def_readwrite("jerk_limits_feed", &CuttingConditions::jerkLimitsFeed,
                     "the real feed also ≤ ∛(J·Rc²) of the plan axes (beyond the paper)");
  py::class_<DirectionSettings>(m, "DirectionSettings", "Sampling of the face and of the directions")
      .def(py::init<>())
      .def_readwrite("grid_u", &DirectionSettings::gridU)
      .def_readwrite("grid_v", &DirectionSettings::gridV)
      .def_readwrite("angle_step", &DirectionSettings::angleStepDeg, "degrees")
      .def_readwrite("report_alpha", &DirectionSettings::reportAlpha);
  m.def(
      "optimal_direction",
      [](const std::string& faceBrep, const CuttingConditions& c, const kinematics::MachineModel& machine,
         const DirectionSettings& s) {
        const TopoDS_Face face = geometry::singleFace(geometry::readBrep(faceBrep));
        py::gil_scoped_release release;
        return guarded("machining direction", [&] { return optimalDirection(face, c, machine, s); });
      },
      py::arg("face_brep"), py::arg("conditions"), py::arg("machine"), py::arg("settings"),
      "Directional beams on the machine's slowest plan axes");
  m.def("beam_algorithm_alpha", &beamAlgorithmAlpha, py::arg("rate"), py::arg("start") = 0.5, py::arg("step") = 0.1,
        py::arg("precision") = 1e-6, "The paper's Fig. 8 algorithm on a rate per direction");
}

}  // namespace hsm::bindings
