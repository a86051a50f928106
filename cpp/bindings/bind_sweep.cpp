// Bindings of the roughing sweep, its clearance check and the material-removal simulation
// (cpp/roughing/sweep.hpp, clearance.hpp, removal.hpp): thin, the moves as numpy arrays.
#include "bindings/bindings.hpp"

#include "common/text.hpp"
#include "geometry/brep.hpp"
#include "roughing/clearance.hpp"
#include "roughing/reach.hpp"
#include "roughing/removal.hpp"
#include "roughing/sweep.hpp"

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>

namespace py = pybind11;

namespace hsm::bindings {

namespace {
using namespace roughing;

// The moves as a dict of arrays: tip (N, 3), axis (N, 3), kind (N, index in MOVE_KINDS), sub_volume (N).
py::dict moveArrays(const std::vector<ToolMove>& moves) {
  const auto n = static_cast<py::ssize_t>(moves.size());
  py::array_t<double> tip({n, py::ssize_t(3)}), axis({n, py::ssize_t(3)});
  py::array_t<long> kind(n), sub(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const ToolMove& m = moves[static_cast<size_t>(i)];
    for (int k = 0; k < 3; ++k) {
      tip.mutable_at(i, k) = m.tip[k];
      axis.mutable_at(i, k) = m.axis[k];
    }
    kind.mutable_at(i) = static_cast<long>(m.kind);
    sub.mutable_at(i) = m.subVolume;
  }
  py::dict d;
  d["tip"] = tip;
  d["axis"] = axis;
  d["kind"] = kind;
  d["sub_volume"] = sub;
  return d;
}

py::array_t<double> pointArray(const std::vector<Eigen::Vector3d>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t(3)});
  for (size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) out.mutable_at(static_cast<py::ssize_t>(i), k) = points[i][k];
  return out;
}

RestStock restFrom(const py::array_t<double>& points, double spacing) {
  if (points.ndim() != 2 || points.shape(1) != 3) throw InputError("rest stock points must be an (N, 3) array");
  RestStock rest;
  rest.spacing = spacing;
  for (py::ssize_t i = 0; i < points.shape(0); ++i) rest.points.emplace_back(points.at(i, 0), points.at(i, 1), points.at(i, 2));
  return rest;
}

std::vector<ToolMove> movesFrom(const py::array_t<double>& tips, const py::array_t<double>& axes,
                                const std::optional<py::array_t<long>>& kinds = std::nullopt) {
  if (tips.ndim() != 2 || tips.shape(1) != 3 || axes.ndim() != 2 || axes.shape(1) != 3 || axes.shape(0) != tips.shape(0))
    throw InputError("tips and axes must be (N, 3) arrays of the same N");
  if (kinds && (kinds->ndim() != 1 || kinds->shape(0) != tips.shape(0)))
    throw InputError("kinds must be an (N,) array of indices in MOVE_KINDS, one per tip");
  std::vector<ToolMove> moves(static_cast<size_t>(tips.shape(0)));
  for (py::ssize_t i = 0; i < tips.shape(0); ++i) {
    ToolMove& m = moves[static_cast<size_t>(i)];
    m.tip = Eigen::Vector3d(tips.at(i, 0), tips.at(i, 1), tips.at(i, 2));
    m.axis = Eigen::Vector3d(axes.at(i, 0), axes.at(i, 1), axes.at(i, 2));
    if (!m.tip.allFinite() || !(m.axis.norm() > 1e-9))
      throw InputError("move " + std::to_string(i) + ": its tip must be finite and its axis not zero");
    m.axis.normalize();
    if (kinds) {
      const long k = kinds->at(i);
      if (k < 0 || k > static_cast<long>(MoveKind::Link))
        throw InputError("move " + std::to_string(i) + ": kind " + std::to_string(k) + " is not an index in MOVE_KINDS");
      m.kind = static_cast<MoveKind>(k);
    }
  }
  return moves;
}

// Operations as (moves dict, Cutter) pairs: the runs of a program of several tools.
std::vector<ToolRun> runsFrom(const std::vector<py::tuple>& runs) {
  std::vector<ToolRun> out;
  for (const py::tuple& run : runs) {
    if (run.size() != 2) throw InputError("each run is (moves, cutter): moves a dict of tip, axis and kind arrays");
    const py::dict d = run[0].cast<py::dict>();
    out.push_back({movesFrom(d["tip"].cast<py::array_t<double>>(), d["axis"].cast<py::array_t<double>>(),
                             d["kind"].cast<py::array_t<long>>()),
                   run[1].cast<Cutter>()});
  }
  return out;
}
}  // namespace

void bindSweep(py::module_& m) {
  py::enum_<CutterKind>(m, "CutterKind").value("flat", CutterKind::Flat).value("torus", CutterKind::Torus)
      .value("ball", CutterKind::Ball);
  py::class_<Cutter>(m, "Cutter", "The cutter and its holder, mm")
      .def(py::init<>())
      .def_readwrite("kind", &Cutter::kind)
      .def_readwrite("diameter", &Cutter::diameter)
      .def_readwrite("corner_radius", &Cutter::cornerRadius)
      .def_readwrite("flute_length", &Cutter::fluteLength)
      .def_readwrite("shank_diameter", &Cutter::shankDiameter)
      .def_readwrite("stick_out", &Cutter::stickOut, "from the tip to the holder")
      .def_readwrite("holder_diameter", &Cutter::holderDiameter)
      .def_readwrite("holder_length", &Cutter::holderLength)
      .def("profile_radius", &Cutter::profileRadius, py::arg("height"), "radius at a height above the tip");
  py::class_<RestStock>(m, "RestStock", "Stock a previous operation left: points `spacing` mm apart, beyond the allowance")
      .def(py::init<>())
      .def(py::init(&restFrom), py::arg("points"), py::arg("spacing"))
      .def_property_readonly("points", [](const RestStock& r) { return pointArray(r.points); }, "(N, 3), mm")
      .def_readonly("spacing", &RestStock::spacing, "mm; each point stands for a cube of that side")
      .def_property_readonly("volume", [](const RestStock& r) { return double(r.points.size()) * std::pow(r.spacing, 3); },
                             "mm³, as the points stand for it")
      .def("__len__", [](const RestStock& r) { return r.points.size(); });
  py::class_<SweepSettings>(m, "SweepSettings", "Sweeping of the sub-volumes (mm, degrees)")
      .def(py::init<>())
      .def_readwrite("cutter", &SweepSettings::cutter)
      .def_readwrite("radial_engagement", &SweepSettings::radialEngagement, "share of the diameter, ]0, 1]")
      .def_readwrite("allowance", &SweepSettings::allowance)
      .def_readwrite("tolerance", &SweepSettings::tolerance)
      .def_readwrite("ramp_angle_deg", &SweepSettings::rampAngleDeg)
      .def_readwrite("clearance", &SweepSettings::clearance)
      .def_readwrite("mesh_deflection", &SweepSettings::meshDeflection)
      .def_readwrite("step_up_minimum", &SweepSettings::stepUpMinimum, "mm between intermediate levels; 0: none")
      .def_readwrite("step_up_scallop", &SweepSettings::stepUpScallop, "mm of staircase left across a wall")
      .def_readwrite("push_out_most", &SweepSettings::pushOutMost,
                     "mm a level's boundary may move from the keep-out towards the part, to the exact clearance; 0: off")
      .def_readwrite("rest", &SweepSettings::rest, "rest roughing: cut only where the tool reaches this stock");
  std::vector<std::string> kinds;
  for (MoveKind k : {MoveKind::Rapid, MoveKind::Plunge, MoveKind::Ramp, MoveKind::Cut, MoveKind::Link})
    kinds.push_back(moveKindName(k));
  m.attr("MOVE_KINDS") = kinds;
  py::class_<Pass>(m, "Pass")
      .def_readonly("sub_volume", &Pass::subVolume)
      .def_readonly("ring", &Pass::ring, "0 for the domain's boundary, k for its k-th offset")
      .def_readonly("closed", &Pass::closed, "a loop, or an open path")
      .def_readonly("intermediate", &Pass::intermediate, "on a level between a slice's far and near sides")
      .def_readonly("depth", &Pass::depth, "the ring's offset inward from the level's domain, mm laid flat")
      .def_readonly("points", &Pass::points);
  py::class_<SweepResult>(m, "SweepResult", "Lengths in mm")
      .def_property_readonly("moves", [](const SweepResult& r) { return moveArrays(r.moves); })
      .def_readonly("passes", &SweepResult::passes)
      .def_readonly("cutting_length", &SweepResult::cuttingLength)
      .def_readonly("ramp_length", &SweepResult::rampLength)
      .def_readonly("link_length", &SweepResult::linkLength)
      .def_readonly("rapid_length", &SweepResult::rapidLength)
      .def_readonly("retracts", &SweepResult::retracts)
      .def_readonly("ramps", &SweepResult::ramps)
      .def_readonly("plunges", &SweepResult::plunges)
      .def_readonly("warnings", &SweepResult::warnings);
  m.def(
      "sweep",
      [](const Partition& partition, const RemovalSolid& solid, const std::string& partBrep,
         const std::string& stockBrep, SweepSettings settings, const py::object& progress) {
        const TopoDS_Shape part = geometry::readBrep(partBrep), stock = geometry::readBrep(stockBrep);
        settings.progress = progressCallback(progress);
        py::gil_scoped_release release;
        return guarded("sweep", [&] { return sweep(partition, solid, part, stock, settings); });
      },
      py::arg("partition"), py::arg("solid"), py::arg("part_brep"), py::arg("stock_brep"), py::arg("settings"),
      py::arg("progress") = py::none());
  py::class_<ClearanceReport>(m, "ClearanceReport")
      .def_readonly("minimum", &ClearanceReport::minimum, "mm, the least distance from the tool to the part")
      .def_readonly("positions", &ClearanceReport::positions)
      .def_readonly("too_close", &ClearanceReport::tooClose)
      .def_readonly("worst_move", &ClearanceReport::worstMove)
      .def_readonly("worst_tip", &ClearanceReport::worstTip)
      .def_property_readonly("move_minimum", [](const ClearanceReport& r) {
        return py::array_t<double>(r.moveMinimum.size(), r.moveMinimum.data());
      }, "per move, the least distance along it, mm (capped at the limit + 2)");
  m.def(
      "check_clearance",
      [](const py::array_t<double>& tips, const py::array_t<double>& axes, const std::string& partBrep,
         const Cutter& cutter, double limit, double spacing, double deflection) {
        const std::vector<ToolMove> moves = movesFrom(tips, axes);
        const TopoDS_Shape part = geometry::readBrep(partBrep);
        py::gil_scoped_release release;
        return guarded("clearance check", [&] { return checkClearance(moves, part, cutter, limit, spacing, deflection); });
      },
      py::arg("tips"), py::arg("axes"), py::arg("part_brep"), py::arg("cutter"), py::arg("limit"),
      py::arg("spacing") = 1.0, py::arg("deflection") = 0.01);
  m.def(
      "join_sweeps",
      [](const std::vector<py::dict>& regions, const std::string& stockBrep, double clearance) {
        std::vector<std::vector<ToolMove>> moves;
        for (const py::dict& d : regions)
          moves.push_back(movesFrom(d["tip"].cast<py::array_t<double>>(), d["axis"].cast<py::array_t<double>>(),
                                    d["kind"].cast<py::array_t<long>>()));
        const TopoDS_Shape stock = geometry::readBrep(stockBrep);
        py::gil_scoped_release release;
        const std::vector<ToolMove> joined = guarded("joining sweeps", [&] { return joinSweeps(moves, stock, clearance); });
        py::gil_scoped_acquire acquire;
        return moveArrays(joined);
      },
      py::arg("regions"), py::arg("stock_brep"), py::arg("clearance") = 5.0);
  py::class_<RemovalSettings>(m, "RemovalSettings", "Material-removal simulation (mm)")
      .def(py::init<>())
      .def_readwrite("resolution", &RemovalSettings::resolution, "mm between rays (default 0.2)")
      .def_readwrite("chip_section", &RemovalSettings::chipSection, "mm², the least chip of a position in material")
      .def_readwrite("stick_out_spacing", &RemovalSettings::stickOutSpacing, "mm of path between stick-out measures")
      .def_readwrite("threads", &RemovalSettings::threads, "0: all cores")
      .def_readwrite("allowance", &RemovalSettings::allowance, "mm of stock meant to stay on the part")
      .def_readwrite("stock_mesh_stride", &RemovalSettings::stockMeshStride,
                     "> 0: the stock left as blocks of stride x stride rays (0: none)")
      .def_readwrite("rest_spacing", &RemovalSettings::restSpacing,
                     "> 0: the stock left beyond the allowance as points this far apart (rest roughing), mm");
  py::class_<RapidFault>(m, "RapidFault", "A rapid that cuts the stock left")
      .def_readonly("move", &RapidFault::move, "index of the rapid in the moves")
      .def_readonly("at", &RapidFault::at, "the tip where it first cuts, mm")
      .def_readonly("along", &RapidFault::along, "share of the move's length before it cuts")
      .def_readonly("volume", &RapidFault::volume, "mm³ it takes out")
      .def("__repr__", [](const RapidFault& f) {
        return "<RapidFault move " + std::to_string(f.move) + " at (" + number(f.at.x()) + ", " + number(f.at.y()) +
               ", " + number(f.at.z()) + ") " + number(f.volume) + " mm3>";
      });
  py::class_<RemovalResult>(m, "RemovalResult", "Lengths mm, volumes mm³, shares %")
      .def_readonly("resolution", &RemovalResult::resolution)
      .def_readonly("volume_to_remove", &RemovalResult::volumeToRemove)
      .def_readonly("remaining_volume", &RemovalResult::remainingVolume)
      .def_readonly("remaining_share", &RemovalResult::remainingShare, "V_r, % of the volume to remove")
      .def_readonly("beyond_allowance_volume", &RemovalResult::beyondAllowanceVolume)
      .def_readonly("beyond_allowance_share", &RemovalResult::beyondAllowanceShare,
                    "V_r without the allowance layer left on the part, %")
      .def_readonly("path_length", &RemovalResult::pathLength)
      .def_readonly("feed_length", &RemovalResult::feedLength)
      .def_readonly("in_material_length", &RemovalResult::inMaterialLength)
      .def_readonly("in_material_share", &RemovalResult::inMaterialShare, "% of the feed length")
      .def_readonly("in_material_path_share", &RemovalResult::inMaterialPathShare,
                    "% of the whole path length (rapids and links too)")
      .def_readonly("stick_out", &RemovalResult::stickOut, "least stick-out for the holder to clear everything")
      .def_readonly("stick_out_move", &RemovalResult::stickOutMove)
      .def_readonly("gouge_volume", &RemovalResult::gougeVolume)
      .def_readonly("gouge_move", &RemovalResult::gougeMove)
      .def_readonly("gouge_at", &RemovalResult::gougeAt)
      .def_readonly("rapid_faults", &RemovalResult::rapidFaults, "rapids that cut the stock left (faults)")
      .def_readonly("rapid_volume", &RemovalResult::rapidVolume, "mm³ the rapids take out")
      .def_property_readonly("surface_points", [](const RemovalResult& r) { return pointArray(r.surfacePoints); })
      .def_readonly("rest", &RemovalResult::rest, "the stock left beyond the allowance (with rest_spacing)")
      .def_property_readonly("thickness", [](const RemovalResult& r) { return py::array_t<double>(r.thickness.size(), r.thickness.data()); })
      .def_property_readonly("weight", [](const RemovalResult& r) { return py::array_t<double>(r.weight.size(), r.weight.data()); })
      .def_readonly("thickness_mean", &RemovalResult::thicknessMean)
      .def_readonly("thickness_max", &RemovalResult::thicknessMax)
      .def_readonly("thickness_std", &RemovalResult::thicknessStd)
      .def_property_readonly("stock_mesh", [](const RemovalResult& r) {
        // (points (N, 3), triangles (M, 3)): the stock left, closed (empty without stock_mesh_stride).
        py::array_t<double> points({static_cast<py::ssize_t>(r.stockMesh.vertices.size()), py::ssize_t(3)});
        py::array_t<long> triangles({static_cast<py::ssize_t>(r.stockMesh.triangles.size()), py::ssize_t(3)});
        for (size_t i = 0; i < r.stockMesh.vertices.size(); ++i)
          for (int k = 0; k < 3; ++k) points.mutable_at(static_cast<py::ssize_t>(i), k) = r.stockMesh.vertices[i][k];
        for (size_t i = 0; i < r.stockMesh.triangles.size(); ++i)
          for (int k = 0; k < 3; ++k) triangles.mutable_at(static_cast<py::ssize_t>(i), k) = r.stockMesh.triangles[i][k];
        return py::make_tuple(points, triangles);
      })
      .def_readonly("rays", &RemovalResult::rays)
      .def_readonly("positions", &RemovalResult::positions);
  m.def(
      "simulate_removal",
      [](const py::array_t<double>& tips, const py::array_t<double>& axes, const py::array_t<long>& kinds,
         const Cutter& cutter, const std::string& stockBrep, const std::string& partBrep, RemovalSettings settings,
         const py::object& progress) {
        const std::vector<ToolMove> moves = movesFrom(tips, axes, kinds);
        const TopoDS_Shape stock = geometry::readBrep(stockBrep), part = geometry::readBrep(partBrep);
        settings.progress = progressCallback(progress);
        py::gil_scoped_release release;
        return guarded("material removal", [&] { return simulateRemoval(moves, cutter, stock, part, settings); });
      },
      py::arg("tips"), py::arg("axes"), py::arg("kinds"), py::arg("cutter"), py::arg("stock_brep"),
      py::arg("part_brep"), py::arg("settings"), py::arg("progress") = py::none());
  py::class_<LeftSplit>(m, "LeftSplit", "What a roughing path leaves, by cause (mm³)")
      .def_readonly("resolution", &LeftSplit::resolution, "mm, the grid of columns and heights")
      .def_readonly("volume", &LeftSplit::volume, "mm³ of the solid's material as sampled")
      .def_readonly("unreachable", &LeftSplit::unreachable, "mm³ no tool position along these axes reaches")
      .def_readonly("between_levels", &LeftSplit::betweenLevels, "mm³ reached only from between the path's levels")
      .def_readonly("levels", &LeftSplit::levels, "the path's distinct cutting heights");
  m.def(
      "split_what_is_left",
      [](const Partition& partition, const RemovalSolid& solid, const std::string& partBrep, const Cutter& cutter,
         double allowance, const py::array_t<double>& tips, const py::array_t<double>& axes,
         const py::array_t<long>& kinds, double resolution, int threads) {
        const std::vector<ToolMove> moves = movesFrom(tips, axes, kinds);
        const TopoDS_Shape part = geometry::readBrep(partBrep);
        py::gil_scoped_release release;
        return guarded("split of what is left", [&] {
          return splitWhatIsLeft(partition, solid, part, cutter, allowance, moves, resolution, threads);
        });
      },
      py::arg("partition"), py::arg("solid"), py::arg("part_brep"), py::arg("cutter"), py::arg("allowance"),
      py::arg("tips"), py::arg("axes"), py::arg("kinds"), py::arg("resolution") = 0.25, py::arg("threads") = 0);
  m.def(
      "simulate_removal_runs",
      [](const std::vector<py::tuple>& runs, const std::string& stockBrep, const std::string& partBrep,
         RemovalSettings settings, const py::object& progress) {
        const std::vector<ToolRun> toolRuns = runsFrom(runs);
        const TopoDS_Shape stock = geometry::readBrep(stockBrep), part = geometry::readBrep(partBrep);
        settings.progress = progressCallback(progress);
        py::gil_scoped_release release;
        return guarded("material removal", [&] { return simulateRemoval(toolRuns, stock, part, settings); });
      },
      py::arg("runs"), py::arg("stock_brep"), py::arg("part_brep"), py::arg("settings"), py::arg("progress") = py::none());
  m.def(
      "keep_rapids_out_of_stock",
      [](const py::array_t<double>& tips, const py::array_t<double>& axes, const py::array_t<long>& kinds,
         const Cutter& cutter, const std::string& stockBrep, const std::string& partBrep, RemovalSettings settings,
         double margin, const py::object& progress, const std::vector<py::tuple>& before) {
        const std::vector<ToolMove> moves = movesFrom(tips, axes, kinds);
        const std::vector<ToolRun> earlier = runsFrom(before);
        const TopoDS_Shape stock = geometry::readBrep(stockBrep), part = geometry::readBrep(partBrep);
        settings.progress = progressCallback(progress);
        py::gil_scoped_release release;
        RapidsMended mended = guarded("rapids in stock", [&] {
          return keepRapidsOutOfStock(moves, cutter, stock, part, settings, margin, earlier);
        });
        py::gil_scoped_acquire acquire;
        return py::make_tuple(moveArrays(mended.moves), mended.mended);
      },
      py::arg("tips"), py::arg("axes"), py::arg("kinds"), py::arg("cutter"), py::arg("stock_brep"),
      py::arg("part_brep"), py::arg("settings"), py::arg("margin") = 1.0, py::arg("progress") = py::none(),
      py::arg("before") = std::vector<py::tuple>{});
}

}  // namespace hsm::bindings
