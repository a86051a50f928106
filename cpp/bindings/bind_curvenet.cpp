#include "bindings/bindings.hpp"

#include "curvenet/curvenet.hpp"
#include "curvenet/regions.hpp"
#include "geometry/brep.hpp"
#include "geometry/bspline.hpp"

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>

namespace py = pybind11;

namespace hsm::bindings {

namespace {
using curvenet::NetCurve;
using Curve = Handle(Geom_BSplineCurve);

// The settings as given, with the bottom face read from BREP text (a face does not cross to Python).
curvenet::NetSettings withFace(curvenet::NetSettings settings, const std::optional<std::string>& faceBrep) {
  if (faceBrep) settings.face = geometry::singleFace(geometry::readBrep(*faceBrep));
  return settings;
}

py::list regions(const curvenet::CurveNet& net, const std::string& faceBrep) {
  py::list result;
  const TopoDS_Face face = geometry::singleFace(geometry::readBrep(faceBrep));
  const auto found = guarded("split of the bottom face", [&] { return curvenet::areaRegions(net, face); });
  for (const auto& region : found)
    result.append(py::make_tuple(region.area.lower, region.area.upper, geometry::writeBrep(region.faces),
                                 region.surfaceArea));
  return result;
}
}  // namespace

void bindCurvenet(py::module_& m) {
  py::class_<BSplineCurve>(m, "BSplineCurve", "A B-spline curve of the core (mm)")
      .def_property_readonly("degree", [](const BSplineCurve& c) { return c.curve->Degree(); })
      .def_property_readonly("pole_count", [](const BSplineCurve& c) { return c.curve->NbPoles(); })
      .def_property_readonly("length",
                             [](const BSplineCurve& c) { return GCPnts_AbscissaPoint::Length(GeomAdaptor_Curve(c.curve)); })
      .def("sample", [](const BSplineCurve& c, int n) { return geometry::sampleByArcLength(Handle(Geom_Curve)(c.curve), n); },
           py::arg("n"), "(n, 3) points equally spaced by arc length")
      .def("to_brep", [](const BSplineCurve& c) { return geometry::edgeBrep(c.curve); }, "BREP text of an edge");

  m.def("curve_from_brep",
        [](const std::string& brep) {
          return guarded("conversion of the curve", [&] { return BSplineCurve{geometry::toBSpline(geometry::readBrep(brep))}; });
        },
        py::arg("brep"), "Exact B-spline of an edge, a wire or a chain of edges given as BREP text");
  m.def("curve_from_points", [](const geometry::PointArray& points) { return BSplineCurve{geometry::interpolatePoints(points)}; },
        py::arg("points"), "Cubic B-spline through an (N,3) array of points along a curve");

  py::enum_<curvenet::CurveRole>(m, "CurveRole")
      .value("boundary", curvenet::CurveRole::Boundary)
      .value("median", curvenet::CurveRole::Median)
      .value("intermediate", curvenet::CurveRole::Intermediate);
  py::enum_<curvenet::NetMode>(m, "NetMode", "How a net grows between the boundaries")
      .value("b1_to_b2", curvenet::NetMode::B1ToB2)
      .value("b2_to_b1", curvenet::NetMode::B2ToB1)
      .value("median", curvenet::NetMode::Median)
      .value("median_to_boundaries", curvenet::NetMode::MedianToBoundaries)
      .value("boundaries_to_median", curvenet::NetMode::BoundariesToMedian);
  py::class_<curvenet::NetSettings>(m, "NetSettings", "Planes and fit of a net (mm); the bottom face is given apart")
      .def(py::init<>())
      .def_readwrite("step", &curvenet::NetSettings::step, "P, mm: largest distance between two planes")
      .def_readwrite("direction", &curvenet::NetSettings::direction,
                     "machining direction (None: the boundaries' mean chord, snapped to an axis within 10°)")
      .def_readwrite("tool_axis", &curvenet::NetSettings::toolAxis)
      .def_readwrite("fit_tolerance", &curvenet::NetSettings::fitTolerance, "mm")
      .def_readwrite("min_gap", &curvenet::NetSettings::minGap, "mm: stop rule of the iterative nets")
      .def_readwrite("pinch_fraction", &curvenet::NetSettings::pinchFraction)
      .def_readwrite("max_curves_per_net", &curvenet::NetSettings::maxCurvesPerNet);
  py::class_<curvenet::GuidanceSettings>(m, "GuidanceSettings", "The 4-step method: net.step is the initial step")
      .def(py::init<>())
      .def_readwrite("net", &curvenet::GuidanceSettings::net)
      .def_readwrite("k_median", &curvenet::GuidanceSettings::kMedian)
      .def_readwrite("k", &curvenet::GuidanceSettings::k)
      .def_readwrite("min_step", &curvenet::GuidanceSettings::minStep, "mm");

  py::class_<NetCurve>(m, "NetCurve", "A curve of a net: a boundary, the median or an intermediate curve")
      .def_readonly("label", &NetCurve::label)
      .def_readonly("role", &NetCurve::role)
      .def_property_readonly("curve", [](const NetCurve& c) { return BSplineCurve{c.curve}; })
      .def_readonly("points", &NetCurve::points, "construction points, one per plane (empty for boundaries)")
      .def_readonly("k", &NetCurve::k)
      .def_readonly("start", &NetCurve::from, "label of the curve it was built from")
      .def_readonly("target", &NetCurve::towards, "label of the curve it was built towards")
      .def_readonly("net", &NetCurve::net)
      .def_readonly("rank", &NetCurve::rank)
      .def_readonly("fit_deviation", &NetCurve::fitDeviation, "mm")
      .def_property_readonly("degree", [](const NetCurve& c) { return c.curve->Degree(); })
      .def("sample", [](const NetCurve& c, int n) { return geometry::sampleByArcLength(Handle(Geom_Curve)(c.curve), n); },
           py::arg("n"), "(n, 3) points equally spaced by arc length")
      .def("to_brep", [](const NetCurve& c) { return geometry::edgeBrep(c.curve); }, "BREP text of an edge");

  py::class_<curvenet::CurveNet>(m, "CurveNet", "Curves across a bottom feature, from B1 to B2")
      .def_readonly("curves", &curvenet::CurveNet::curves)
      .def_readonly("stations", &curvenet::CurveNet::stations, "plane positions along the direction, mm")
      .def_readonly("direction", &curvenet::CurveNet::direction)
      .def_readonly("warnings", &curvenet::CurveNet::warnings)
      .def("elementary_areas",
           [](const curvenet::CurveNet& n) {
             std::vector<std::pair<int, int>> pairs;
             for (const auto& a : n.elementaryAreas()) pairs.emplace_back(a.lower, a.upper);
             return pairs;
           },
           "(lower, upper) indices of consecutive curves")
      .def("composed_areas",
           [](const curvenet::CurveNet& n) {
             std::vector<std::vector<std::pair<int, int>>> result;
             for (const auto& ma : n.composedAreas()) {
               result.emplace_back();
               for (const auto& a : ma) result.back().emplace_back(a.lower, a.upper);
             }
             return result;
           },
           "MA_1, MA_2…: each a list of (lower, upper) curve indices")
      .def("regions", &regions, py::arg("face_brep"),
           "Per elementary area: (lower, upper, BREP of its faces, surface area mm²)");

  py::class_<curvenet::GuidanceHalf>(m, "GuidanceHalf")
      .def_readonly("start", &curvenet::GuidanceHalf::start)
      .def_readonly("target", &curvenet::GuidanceHalf::target)
      .def_readonly("start_min_radius", &curvenet::GuidanceHalf::startMinRadius)
      .def_readonly("target_min_radius", &curvenet::GuidanceHalf::targetMinRadius)
      .def_readonly("skipped", &curvenet::GuidanceHalf::skipped);
  py::class_<curvenet::GuidanceReport>(m, "GuidanceReport")
      .def_readonly("inflection_stations", &curvenet::GuidanceReport::inflectionStations)
      .def_readonly("smallest_step", &curvenet::GuidanceReport::smallestStep)
      .def_readonly("largest_step", &curvenet::GuidanceReport::largestStep)
      .def_readonly("half1", &curvenet::GuidanceReport::half1)
      .def_readonly("half2", &curvenet::GuidanceReport::half2);

  m.def(
      "intermediate_curve",
      [](const BSplineCurve& a, const BSplineCurve& b, double k, const curvenet::NetSettings& settings,
         const std::optional<std::string>& face) {
        const auto s = withFace(settings, face);
        return guarded("intermediate curve", [&] { return curvenet::intermediateCurve(a.curve, b.curve, k, s); });
      },
      py::arg("a"), py::arg("b"), py::arg("k"), py::arg("settings"), py::arg("face_brep") = py::none());
  m.def(
      "curve_net",
      [](const BSplineCurve& b1, const BSplineCurve& b2, double k, curvenet::NetMode mode,
         const curvenet::NetSettings& settings, const std::optional<std::string>& face, const py::object& progress) {
        auto s = withFace(settings, face);
        s.progress = progressCallback(progress);
        py::gil_scoped_release release;
        return guarded("curve net", [&] { return curvenet::curveNet({b1.curve, b2.curve}, k, mode, s); });
      },
      py::arg("b1"), py::arg("b2"), py::arg("k"), py::arg("mode"), py::arg("settings"),
      py::arg("face_brep") = py::none(), py::arg("progress") = py::none());
  m.def(
      "guidance_curves",
      [](const BSplineCurve& b1, const BSplineCurve& b2, curvenet::GuidanceSettings settings,
         const std::optional<std::string>& face) {
        settings.net = withFace(settings.net, face);
        const auto result =
            guarded("4-step method", [&] { return curvenet::guidanceCurves({b1.curve, b2.curve}, settings); });
        return py::make_tuple(result.net, result.report);
      },
      py::arg("b1"), py::arg("b2"), py::arg("settings"), py::arg("face_brep") = py::none());
}

}  // namespace hsm::bindings
