#include "bindings/bindings.hpp"

#include "kinematics/five_axis.hpp"
#include "kinematics/moves.hpp"
#include "kinematics/report.hpp"
#include "kinematics/simulation.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <sstream>

namespace py = pybind11;

namespace hsm::bindings {

namespace {
using namespace kinematics;

// Per-block results as a dict of numpy arrays (speeds in mm/s, as everywhere inside).
py::dict blockArrays(const std::vector<BlockResult>& blocks) {
  const auto n = static_cast<py::ssize_t>(blocks.size());
  py::array_t<long> line(n), motion(n);
  py::array_t<double> start({n, py::ssize_t(3)}), end({n, py::ssize_t(3)});
  py::array_t<double> center({n, py::ssize_t(3)}), normal({n, py::ssize_t(3)}), sweep(n);
  py::array_t<double> rotaryStart({n, py::ssize_t(2)}), rotaryEnd({n, py::ssize_t(2)});
  py::array_t<double> machineStart({n, py::ssize_t(3)}), machineEnd({n, py::ssize_t(3)});
  py::array_t<long> limit(n);
  py::array_t<bool> rotaryOnly(n);
  const char* names[] = {"length", "programmed_feed", "entry_feed", "exit_feed", "min_feed", "mean_feed",
                         "peak_feed", "start_time", "time"};
  std::vector<py::array_t<double>> columns;
  for (size_t c = 0; c < 9; ++c) columns.emplace_back(n);
  auto l = line.mutable_unchecked<1>();
  auto m = motion.mutable_unchecked<1>();
  auto s = start.mutable_unchecked<2>();
  auto e = end.mutable_unchecked<2>();
  auto c = center.mutable_unchecked<2>();
  auto nn = normal.mutable_unchecked<2>();
  auto sw = sweep.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const BlockResult& b = blocks[static_cast<size_t>(i)];
    l(i) = b.line;
    m(i) = static_cast<long>(b.motion);
    for (int k = 0; k < 3; ++k) {
      s(i, k) = b.start[k];
      e(i, k) = b.end[k];
      c(i, k) = b.center[k];
      nn(i, k) = b.normal[k];
    }
    sw(i) = b.sweep;
    for (int k = 0; k < 2; ++k) {
      rotaryStart.mutable_at(i, k) = b.rotaryStart[k];
      rotaryEnd.mutable_at(i, k) = b.rotaryEnd[k];
    }
    for (int k = 0; k < 3; ++k) {
      machineStart.mutable_at(i, k) = b.machineStart[k];
      machineEnd.mutable_at(i, k) = b.machineEnd[k];
    }
    limit.mutable_at(i) = static_cast<long>(b.limit);
    rotaryOnly.mutable_at(i) = b.rotaryOnly;
    const double values[] = {b.length, b.programmedFeed, b.entryFeed, b.exitFeed, b.minFeed,
                             b.meanFeed, b.peakFeed, b.startTime, b.time};
    for (size_t c = 0; c < 9; ++c) columns[c].mutable_at(i) = values[c];
  }
  py::dict result;
  result["line"] = line;
  result["motion"] = motion;
  result["start"] = start;
  result["end"] = end;
  result["center"] = center;
  result["normal"] = normal;
  result["sweep"] = sweep;
  result["rotary_start"] = rotaryStart;  // deg, the machine's rotary axes in chain order
  result["rotary_end"] = rotaryEnd;
  result["machine_start"] = machineStart;  // X Y Z of the machine, mm
  result["machine_end"] = machineEnd;
  result["limit"] = limit;  // index in SPEED_LIMITS
  result["rotary_only"] = rotaryOnly;
  for (size_t c = 0; c < 9; ++c) result[names[c]] = columns[c];
  return result;
}

py::array_t<double> traceArray(const std::vector<TraceSample>& trace) {
  py::array_t<double> array({static_cast<py::ssize_t>(trace.size()), py::ssize_t(5)});
  auto a = array.mutable_unchecked<2>();
  for (size_t i = 0; i < trace.size(); ++i) {
    const TraceSample& t = trace[i];
    const double row[] = {t.t, t.x, t.y, t.z, t.v};
    for (int k = 0; k < 5; ++k) a(static_cast<py::ssize_t>(i), k) = row[k];
  }
  return array;
}

SimulationOptions simulationOptions(bool keepBlocks, double tracePeriod) {
  SimulationOptions options;
  options.keepBlocks = keepBlocks;
  options.tracePeriod = tracePeriod;
  return options;
}

ReaderOptions readerOptions(bool refuseUnknown, bool feedPerSecond, bool skipUnknown) {
  ReaderOptions reading;
  reading.refuseUnknownWords = refuseUnknown;
  reading.skipUnknownMotion = skipUnknown;
  reading.feedInMmPerSecond = feedPerSecond;
  return reading;
}

// Long programs: let other Python threads (the GUI) run.
template <class Simulation>
SimulationResult released(Simulation&& simulation) {
  py::gil_scoped_release release;
  return guarded("feed-rate simulation", simulation);
}
}  // namespace

void bindKinematics(py::module_& m) {
  py::enum_<ControllerKind>(m, "ControllerKind", "How the controller plans the path between blocks")
      .value("siemens840d", ControllerKind::Siemens840D)
      .value("linuxcnc", ControllerKind::LinuxCNC)
      .value("grbl", ControllerKind::Grbl);
  py::enum_<RotaryPlanner>(m, "RotaryPlanner", "How blocks that turn rotary axes are planned")
      .value("joint_space", RotaryPlanner::JointSpace)
      .value("linuxcnc", RotaryPlanner::LinuxCnc);
  m.attr("DEFAULT_MACHINE") = kDefaultMachine;
  py::class_<RotaryAxis>(m, "RotaryAxis", "A rotary axis: degrees, deg/s, deg/s², deg/s³")
      .def(py::init<>())
      .def_property(
          "name", [](const RotaryAxis& a) { return std::string(1, a.name); },
          [](RotaryAxis& a, const std::string& name) {
            if (name != "A" && name != "B" && name != "C") throw InputError("a rotary axis is named A, B or C");
            a.name = name[0];
          })
      .def_readwrite("on_table", &RotaryAxis::onTable, "carried by the table (True) or by the head")
      .def_readwrite("direction", &RotaryAxis::direction, "unit axis at zero angles, machine frame")
      .def_readwrite("pivot", &RotaryAxis::pivot, "mm: a point of the axis (table: machine frame; head: from the tip)")
      .def_readwrite("max_velocity", &RotaryAxis::maxVelocity, "deg/s")
      .def_readwrite("rapid_velocity", &RotaryAxis::rapidVelocity, "deg/s")
      .def_readwrite("max_acceleration", &RotaryAxis::maxAcceleration, "deg/s²")
      .def_readwrite("max_jerk", &RotaryAxis::maxJerk, "deg/s³")
      .def_readwrite("min_position", &RotaryAxis::minPosition, "deg")
      .def_readwrite("max_position", &RotaryAxis::maxPosition, "deg")
      .def_readwrite("continuous", &RotaryAxis::continuous);
  py::class_<MachineModel>(m, "MachineModel", "Axis limits and controller behaviour (mm, s inside)")
      .def(py::init<>())
      .def_static("from_json", &machineFromJson, py::arg("text"), py::arg("origin") = "machine file")
      .def_static("load", &loadMachine, py::arg("name_or_file"), py::arg("folders"))
      .def("to_json", &machineToJson)
      .def_readwrite("name", &MachineModel::name)
      .def_readwrite("description", &MachineModel::description)
      .def_readwrite("controller", &MachineModel::controller)
      .def_readwrite("max_velocity", &MachineModel::maxVelocity, "mm/s per axis X, Y, Z")
      .def_readwrite("max_acceleration", &MachineModel::maxAcceleration, "mm/s² per axis")
      .def_readwrite("max_jerk", &MachineModel::maxJerk, "mm/s³ per axis")
      .def_readwrite("rapid_velocity", &MachineModel::rapidVelocity, "mm/s per axis")
      .def_readwrite("velocity_jump", &MachineModel::velocityJump, "mm/s per axis")
      .def_readwrite("interpolation_cycle", &MachineModel::interpolationCycle, "s")
      .def_readwrite("look_ahead_blocks", &MachineModel::lookAheadBlocks)
      .def_readwrite("corner_tolerance", &MachineModel::cornerTolerance, "mm")
      .def_readwrite("jerk_limited_by_default", &MachineModel::jerkLimitedByDefault)
      .def_readwrite("rotary_axes", &MachineModel::rotaryAxes, "chain order: the table's from the bed, then the head's")
      .def_readwrite("tool_axis", &MachineModel::toolAxis)
      .def_readwrite("tool_tip_programmed", &MachineModel::toolTipProgrammed)
      .def_readwrite("rotary_planner", &MachineModel::rotaryPlanner)
      .def_property(
          "dialect", [](const MachineModel& m) { return dialectName(m.conventions.dialect); },
          [](MachineModel& m, const std::string& name) { m.conventions.dialect = dialectFromName(name, "dialect"); },
          "the programs' language: linuxcnc, grbl, siemens-840d, fanuc or haas")
      .def_property(
          "power_on_codes", [](const MachineModel& m) { return m.conventions.powerOnCodes; },
          [](MachineModel& m, const std::string& codes) { m.conventions.powerOnCodes = codes; },
          "G words the control is in before a program's first line, e.g. 'G0 G17 G90 G94 G21 G98'")
      .def_property_readonly("kinematics", &MachineModel::kinematicsName,
                             "'table-table', 'head-table', 'head-head', 'table', 'head' or '' (3 axes)");
  m.def(
      "forward_kinematics",
      [](const MachineModel& machine, const Eigen::Vector3d& linear, const std::array<double, 2>& angles) {
        checkMachine(machine);
        const ToolPose pose = forwardKinematics(machine, {linear, angles});
        return py::make_tuple(pose.tip, pose.axis);
      },
      py::arg("machine"), py::arg("linear"), py::arg("angles"),
      "(tip, tool axis) in the workpiece frame for machine X Y Z (mm) and rotary angles (deg, chain order)");
  m.def(
      "inverse_kinematics",
      [](const MachineModel& machine, const Eigen::Vector3d& tip, const Eigen::Vector3d& axis,
         const std::array<double, 2>& previous) {
        checkMachine(machine);
        const InverseResult r = inverseKinematics(machine, {tip, axis}, previous);
        return py::make_tuple(r.position.linear, r.position.angles, r.singular);
      },
      py::arg("machine"), py::arg("tip"), py::arg("axis"), py::arg("previous") = std::array<double, 2>{0.0, 0.0},
      "(X Y Z, angles, singular) reaching the pose, nearest to `previous` within travel; InputError otherwise");
  m.def(
      "orientation_solutions",
      [](const MachineModel& machine, const Eigen::Vector3d& axis) {
        std::vector<std::array<double, 2>> angles;
        for (const AngleSolution& s : orientationSolutions(machine, axis)) angles.push_back(s.angles);
        return angles;
      },
      py::arg("machine"), py::arg("axis"), "every set of angles (deg, in (-180, 180]) that points the tool along axis");
  std::vector<std::string> limitNames;
  for (int k = 0; k < kSpeedLimitCount; ++k) limitNames.push_back(speedLimitName(static_cast<SpeedLimit>(k)));
  m.attr("SPEED_LIMITS") = limitNames;
  m.def("machine_names", &machineNames, py::arg("folders"));

  py::class_<SimulationSummary>(m, "SimulationSummary", "Times in s, lengths in mm")
      .def_readonly("machine", &SimulationSummary::machine)
      .def_readonly("total_time", &SimulationSummary::totalTime)
      .def_readonly("cutting_time", &SimulationSummary::cuttingTime)
      .def_readonly("rapid_time", &SimulationSummary::rapidTime)
      .def_readonly("dwell_time", &SimulationSummary::dwellTime)
      .def_readonly("naive_time", &SimulationSummary::naiveTime)
      .def_readonly("naive_cutting_time", &SimulationSummary::naiveCuttingTime)
      .def_property_readonly("time_over_naive", &SimulationSummary::timeOverNaive,
                             "simulated time / length-over-feed estimate")
      .def_readonly("block_count", &SimulationSummary::blockCount)
      .def_readonly("cutting_blocks", &SimulationSummary::cuttingBlocks)
      .def_readonly("rapid_blocks", &SimulationSummary::rapidBlocks)
      .def_readonly("cutting_length", &SimulationSummary::cuttingLength)
      .def_readonly("rapid_length", &SimulationSummary::rapidLength)
      .def_property_readonly("feed_classes_blocks", [](const SimulationSummary& s) { return s.feedClasses.blocks; })
      .def_property_readonly("feed_classes_length", [](const SimulationSummary& s) { return s.feedClasses.length; })
      .def_property_readonly("feed_classes_time", [](const SimulationSummary& s) { return s.feedClasses.time; })
      .def_readonly("length_classes", &SimulationSummary::lengthClasses)
      .def_readonly("limit_time", &SimulationSummary::limitTime, "s each of SPEED_LIMITS held the speed")
      .def_property_readonly("unknown_words", [](const SimulationSummary& s) { return s.reader.unknownWords; })
      .def_property_readonly("unknown_word_counts",
                             [](const SimulationSummary& s) { return s.reader.unknownWordCounts; })
      .def_property_readonly("lines", [](const SimulationSummary& s) { return s.reader.lines; })
      .def("to_json", &summaryJson, py::arg("program") = "")
      .def("to_text", &summaryText);
  m.attr("FEED_CLASS_EDGES") = kFeedClassEdges;
  m.attr("LENGTH_CLASS_EDGES_MM") = kLengthClassEdges;

  py::class_<SimulationResult>(m, "SimulationResult")
      .def_readonly("summary", &SimulationResult::summary)
      .def_property_readonly("blocks", [](const SimulationResult& r) { return blockArrays(r.blocks); },
                             "dict of numpy arrays, one entry per block (empty unless blocks were kept)")
      .def_property_readonly("trace", [](const SimulationResult& r) { return traceArray(r.trace); },
                             "(N, 5) array of t, x, y, z, speed (s, mm, mm/s)")
      .def("blocks_csv", [](const SimulationResult& r) { return blocksCsv(r.blocks); },
           "the kept blocks as CSV text, feeds in mm/min");

  m.def(
      "simulate_text",
      [](const std::string& text, const MachineModel& machine, bool keepBlocks, double tracePeriod, bool refuse,
         bool perSecond, bool skip, const std::vector<std::string>& folders) {
        std::istringstream stream(text);
        ReaderOptions reading = readerOptions(refuse, perSecond, skip);
        reading.subroutineFolders = folders;
        return released([&] { return simulate(stream, machine, reading, simulationOptions(keepBlocks, tracePeriod)); });
      },
      py::arg("text"), py::arg("machine"), py::arg("keep_blocks") = false, py::arg("trace_period") = 0.0,
      py::arg("refuse_unknown_words") = false, py::arg("feed_in_mm_per_second") = false, py::arg("skip_unknown") = false,
      py::arg("subroutine_folders") = std::vector<std::string>());
  m.def(
      "simulate_file",
      [](const std::string& path, const MachineModel& machine, bool keepBlocks, double tracePeriod, bool refuse,
         bool perSecond, bool skip, const std::vector<std::string>& folders) {
        ReaderOptions reading = readerOptions(refuse, perSecond, skip);
        reading.subroutineFolders = folders;
        return released([&] { return simulateFile(path, machine, reading, simulationOptions(keepBlocks, tracePeriod)); });
      },
      py::arg("path"), py::arg("machine"), py::arg("keep_blocks") = false, py::arg("trace_period") = 0.0,
      py::arg("refuse_unknown_words") = false, py::arg("feed_in_mm_per_second") = false, py::arg("skip_unknown") = false,
      py::arg("subroutine_folders") = std::vector<std::string>());
  m.def(
      "simulate_moves",
      [](const MoveArray& moves, double feed, const MachineModel& machine, bool keepBlocks, double tracePeriod) {
        return released([&] {
          return simulateBlocks(movesToBlocks(moves, feed), machine, simulationOptions(keepBlocks, tracePeriod));
        });
      },
      py::arg("moves"), py::arg("feed"), py::arg("machine"), py::arg("keep_blocks") = false,
      py::arg("trace_period") = 0.0,
      "A toolpath's (N, 4) moves (x, y, z, rapid flag) as G0/G1 blocks at `feed` mm/s, without G-code text");
}

}  // namespace hsm::bindings
