#include "kinematics/machine.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hsm::kinematics {

namespace {
using nlohmann::json;

constexpr const char* kAxes[] = {"X", "Y", "Z"};

[[noreturn]] void bad(const std::string& origin, const std::string& what) {
  throw InputError(origin + ": " + what);
}

// An optional string or true/false of `node`, its type checked: nlohmann's own message names neither the key
// nor the file.
std::string text(const json& node, const std::string& key, const std::string& origin, const std::string& otherwise) {
  if (!node.contains(key)) return otherwise;
  if (!node.at(key).is_string()) bad(origin, "\"" + key + "\" must be text in quotes, got " + node.at(key).dump());
  return node.at(key).get<std::string>();
}

bool flag(const json& node, const std::string& key, const std::string& origin, bool otherwise) {
  if (!node.contains(key)) return otherwise;
  if (!node.at(key).is_boolean()) bad(origin, "\"" + key + "\" must be true or false, got " + node.at(key).dump());
  return node.at(key).get<bool>();
}

double number(const json& node, const std::string& key, const std::string& origin, double scale, bool positive) {
  if (!node.contains(key)) bad(origin, "missing \"" + key + "\": add it (see docs/machines.md)");
  const json& value = node.at(key);
  if (!value.is_number()) bad(origin, "\"" + key + "\" must be a number, got " + value.dump());
  const double x = value.get<double>();
  if (!std::isfinite(x) || (positive ? x <= 0.0 : x < 0.0))
    bad(origin, "\"" + key + "\" = " + value.dump() + (positive ? " must be positive" : " must be 0 or more"));
  return x * scale;
}

Eigen::Vector3d perAxis(const json& axes, const std::string& key, const std::string& origin, double scale,
                        bool positive) {
  Eigen::Vector3d result;
  for (int i = 0; i < 3; ++i) {
    if (!axes.contains(kAxes[i])) bad(origin, std::string("missing axis \"") + kAxes[i] + "\" in \"axes\"");
    result[i] = number(axes.at(kAxes[i]), key, origin + " axis " + kAxes[i], scale, positive);
  }
  return result;
}

ControllerKind controllerKind(const std::string& name, const std::string& origin) {
  if (name == "siemens-840d") return ControllerKind::Siemens840D;
  if (name == "linuxcnc") return ControllerKind::LinuxCNC;
  if (name == "grbl") return ControllerKind::Grbl;
  bad(origin, "controller \"" + name + "\" is unknown: use siemens-840d, linuxcnc or grbl");
}

RotaryPlanner rotaryPlanner(const json& root, const MachineModel& m, const std::string& origin) {
  const bool linuxcnc = m.controller == ControllerKind::LinuxCNC;
  const std::string name = text(root, "planner", origin, linuxcnc ? "linuxcnc" : "joint-space");
  if (name == "joint-space") return RotaryPlanner::JointSpace;
  if (name == "linuxcnc") return RotaryPlanner::LinuxCnc;
  bad(origin, "\"planner\": \"" + name + "\" is unknown: use joint-space or linuxcnc (see docs/machines.md)");
}

constexpr double kPerMinute = 1.0 / 60.0;  // mm/min -> mm/s
constexpr double kMetres = 1000.0;         // m/s², m/s³ -> mm/s², mm/s³

Eigen::Vector3d vector3(const json& node, const std::string& key, const std::string& origin) {
  if (!node.contains(key)) bad(origin, "missing \"" + key + "\": add it (see docs/machines.md)");
  const json& value = node.at(key);
  if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
      !value[2].is_number())
    bad(origin, "\"" + key + "\" must be three numbers [x, y, z], got " + value.dump());
  Eigen::Vector3d v(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
  if (!v.allFinite() || v.cwiseAbs().maxCoeff() > 1e6) bad(origin, "\"" + key + "\" = " + value.dump() + " is out of range");
  return v;
}

RotaryAxis rotaryAxis(const json& node, const std::string& origin) {
  if (!node.is_object()) bad(origin, "each rotary axis must be an object, got " + node.dump());
  RotaryAxis axis;
  const std::string name = text(node, "name", origin + " rotary axis", "");
  if (name != "A" && name != "B" && name != "C") bad(origin, "a rotary axis needs \"name\": \"A\", \"B\" or \"C\"");
  axis.name = name[0];
  const std::string where = origin + " rotary axis " + name;
  const std::string carrier = text(node, "carrier", where, "");
  if (carrier != "table" && carrier != "head") bad(where, "\"carrier\" must be \"table\" or \"head\"");
  axis.onTable = carrier == "table";
  axis.direction = vector3(node, "direction", where);
  if (axis.direction.norm() < 1e-9) bad(where, "\"direction\" must not be zero");
  axis.direction.normalize();
  axis.pivot = vector3(node, "pivot_mm", where);
  axis.maxVelocity = number(node, "max_velocity_deg_min", where, kPerMinute, true);
  axis.rapidVelocity = number(node, "rapid_velocity_deg_min", where, kPerMinute, true);
  axis.maxAcceleration = number(node, "max_acceleration_deg_s2", where, 1.0, true);
  axis.maxJerk = number(node, "max_jerk_deg_s3", where, 1.0, true);
  axis.continuous = flag(node, "continuous", where, false);
  if (!axis.continuous) {
    if (!node.contains("min_deg") || !node.contains("max_deg") || !node["min_deg"].is_number() ||
        !node["max_deg"].is_number())
      bad(where, "needs \"min_deg\" and \"max_deg\" (its travel), or \"continuous\": true");
    axis.minPosition = node["min_deg"].get<double>();
    axis.maxPosition = node["max_deg"].get<double>();
  }
  return axis;
}

json rotaryAxisJson(const RotaryAxis& a) {
  json node = {{"name", std::string(1, a.name)},
               {"carrier", a.onTable ? "table" : "head"},
               {"direction", {a.direction.x(), a.direction.y(), a.direction.z()}},
               {"pivot_mm", {a.pivot.x(), a.pivot.y(), a.pivot.z()}},
               {"max_velocity_deg_min", a.maxVelocity * 60.0},
               {"rapid_velocity_deg_min", a.rapidVelocity * 60.0},
               {"max_acceleration_deg_s2", a.maxAcceleration},
               {"max_jerk_deg_s3", a.maxJerk},
               {"continuous", a.continuous}};
  if (!a.continuous) {
    node["min_deg"] = a.minPosition;
    node["max_deg"] = a.maxPosition;
  }
  return node;
}
}  // namespace

std::string MachineModel::kinematicsName() const {
  std::string name;
  for (auto it = rotaryAxes.rbegin(); it != rotaryAxes.rend(); ++it) {  // head first, as the trade names them
    const std::string part = it->onTable ? "table" : "head";
    if (name.empty()) name = part;
    else name += "-" + part;
  }
  return name;
}

int MachineModel::rotaryIndex(char name) const {
  for (size_t i = 0; i < rotaryAxes.size(); ++i)
    if (rotaryAxes[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string controllerName(ControllerKind kind) {
  switch (kind) {
    case ControllerKind::Siemens840D: return "siemens-840d";
    case ControllerKind::LinuxCNC: return "linuxcnc";
    case ControllerKind::Grbl: return "grbl";
  }
  return "?";
}

std::string rotaryPlannerName(RotaryPlanner planner) {
  return planner == RotaryPlanner::LinuxCnc ? "linuxcnc" : "joint-space";
}

void checkMachine(const MachineModel& m) {
  auto check = [&](double value, double low, double high, const std::string& what, double display,
                   const std::string& unit) {
    if (!(value >= low && value <= high))
      throw InputError("machine \"" + m.name + "\": " + what + " = " + hsm::number(value * display) + " " + unit +
                       " is outside [" + hsm::number(low * display) + ", " + hsm::number(high * display) + "] " + unit);
  };
  for (int i = 0; i < 3; ++i) {
    const std::string axis = std::string(" of axis ") + kAxes[i];
    check(m.maxVelocity[i], 1e-3, 1e6, "max velocity" + axis, 60.0, "mm/min");
    check(m.rapidVelocity[i], 1e-3, 1e6, "rapid velocity" + axis, 60.0, "mm/min");
    check(m.maxAcceleration[i], 1e-3, 1e9, "max acceleration" + axis, 1e-3, "m/s²");
    check(m.maxJerk[i], 1e-3, 1e12, "max jerk" + axis, 1e-3, "m/s³");
    check(m.velocityJump[i], 0.0, 1e6, "velocity jump" + axis, 60.0, "mm/min");
  }
  check(m.interpolationCycle, 0.0, 1.0, "interpolation cycle", 1e3, "ms");
  check(m.lookAheadBlocks, 1, 100000, "look-ahead", 1.0, "blocks");
  check(m.cornerTolerance, 0.0, 10.0, "corner tolerance", 1.0, "mm");
  check(m.arcTolerance, 1e-4, 1.0, "arc tolerance", 1.0, "mm");
  check(m.compressorPathLimit, 0.0, 1000.0, "compressor path limit", 1.0, "mm");
  checkRotaryAxes(m);
  if (m.rotaryPlanner == RotaryPlanner::LinuxCnc && m.controller != ControllerKind::LinuxCNC)
    throw InputError("machine \"" + m.name + "\": planner linuxcnc is LinuxCNC's own; controller " +
                     controllerName(m.controller) + " plans in joint space (planner joint-space)");
}

void checkRotaryAxes(const MachineModel& m) {
  const std::string machine = "machine \"" + m.name + "\": ";
  if (m.rotaryAxes.size() > 2)
    throw InputError(machine + std::to_string(m.rotaryAxes.size()) + " rotary axes: a machine has at most two");
  if (!(std::abs(m.toolAxis.norm() - 1.0) < 1e-9))
    throw InputError(machine + "the tool axis must be a unit vector");
  bool headSeen = false;
  for (size_t i = 0; i < m.rotaryAxes.size(); ++i) {
    const RotaryAxis& a = m.rotaryAxes[i];
    const std::string axis = machine + "rotary axis " + std::string(1, a.name) + ": ";
    if (a.name != 'A' && a.name != 'B' && a.name != 'C') throw InputError(machine + "rotary axes are named A, B or C");
    if (m.rotaryIndex(a.name) != static_cast<int>(i)) throw InputError(axis + "named twice");
    if (a.onTable && headSeen)
      throw InputError(axis + "a table axis after a head axis: list the table's axes first (bed outwards)");
    headSeen = headSeen || !a.onTable;
    if (!(std::abs(a.direction.norm() - 1.0) < 1e-9) || !a.pivot.allFinite())
      throw InputError(axis + "its direction must be a unit vector and its pivot finite");
    auto check = [&](double value, double low, double high, const std::string& what, double display,
                     const std::string& unit) {
      if (!(value >= low && value <= high))
        throw InputError(axis + what + " = " + hsm::number(value * display) + " " + unit + " is outside [" +
                         hsm::number(low * display) + ", " + hsm::number(high * display) + "] " + unit);
    };
    check(a.maxVelocity, 1e-3, 1e5, "max velocity", 60.0, "deg/min");
    check(a.rapidVelocity, 1e-3, 1e5, "rapid velocity", 60.0, "deg/min");
    check(a.maxAcceleration, 1e-3, 1e7, "max acceleration", 1.0, "deg/s²");
    check(a.maxJerk, 1e-3, 1e9, "max jerk", 1.0, "deg/s³");
    if (!a.continuous && !(a.minPosition < a.maxPosition && a.minPosition >= -1e5 && a.maxPosition <= 1e5))
      throw InputError(axis + "travel [" + hsm::number(a.minPosition) + ", " + hsm::number(a.maxPosition) +
                       "] deg must be an interval within ±100000 deg");
  }
  if (m.rotaryAxes.size() == 2 && m.rotaryAxes[0].direction.cross(m.rotaryAxes[1].direction).norm() < 1e-6)
    throw InputError(machine + "the two rotary axes are parallel: they cannot orient the tool");
}

static MachineModel machineFromJsonChecked(const std::string& source, const std::string& origin);

namespace {
Dialect defaultDialect(ControllerKind controller) {
  switch (controller) {
    case ControllerKind::Siemens840D: return Dialect::Siemens840D;
    case ControllerKind::Grbl: return Dialect::Grbl;
    default: return Dialect::LinuxCnc;
  }
}

ControlConventions conventions(const json& root, ControllerKind controller, const std::string& origin) {
  ControlConventions c;
  c.dialect = dialectFromName(text(root, "dialect", origin, dialectName(defaultDialect(controller))), origin);
  c.powerOnCodes = text(root, "power_on_codes", origin, "");
  for (const char ch : c.powerOnCodes)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == ' ' || ch == '.' || ch == '-'))
      bad(origin, "\"power_on_codes\" holds G words such as \"G0 G17 G90 G94 G21 G98\", not '" + std::string(1, ch) + "'");
  const std::string decimal = text(root, "decimal_point", origin, "whole-units");
  if (decimal != "whole-units" && decimal != "least-increment")
    bad(origin, "\"decimal_point\": \"" + decimal + "\" is unknown: \"whole-units\" (X100 is 100 mm) or "
                "\"least-increment\" (X100 is 0.1 mm, a Fanuc with parameter DPI off)");
  c.leastIncrementInput = decimal == "least-increment";
  if (root.contains("work_offset_mm")) c.workOffset = vector3(root, "work_offset_mm", origin);
  return c;
}
}  // namespace

MachineModel machineFromJson(const std::string& source, const std::string& origin) {
  try {
    return machineFromJsonChecked(source, origin);
  } catch (const json::exception& error) {  // a type no check above foresaw: still the file's fault, by name
    bad(origin, std::string("a value of the wrong type (") + error.what() + "): see docs/machines.md");
  }
}

static MachineModel machineFromJsonChecked(const std::string& source, const std::string& origin) {
  json root;
  try {
    root = json::parse(source);
  } catch (const json::parse_error& error) {
    bad(origin, std::string("not valid JSON (") + error.what() + ")");
  }
  if (!root.is_object()) bad(origin, "the top level must be an object");
  MachineModel m;
  m.name = text(root, "name", origin, "");
  if (m.name.empty()) bad(origin, "missing \"name\"");
  m.description = text(root, "description", origin, "");
  if (!root.contains("controller") || !root["controller"].is_string()) bad(origin, "missing \"controller\"");
  m.controller = controllerKind(root["controller"].get<std::string>(), origin);
  if (!root.contains("axes") || !root["axes"].is_object()) bad(origin, "missing \"axes\" with X, Y and Z");
  const json& axes = root["axes"];
  m.maxVelocity = perAxis(axes, "max_velocity_mm_min", origin, kPerMinute, true);
  m.maxAcceleration = perAxis(axes, "max_acceleration_m_s2", origin, kMetres, true);
  m.maxJerk = perAxis(axes, "max_jerk_m_s3", origin, kMetres, true);
  m.rapidVelocity = perAxis(axes, "rapid_velocity_mm_min", origin, kPerMinute, true);
  m.velocityJump = perAxis(axes, "velocity_jump_mm_min", origin, kPerMinute, false);
  m.interpolationCycle = number(root, "interpolation_cycle_ms", origin, 1e-3, false);
  const double lookAhead = number(root, "look_ahead_blocks", origin, 1.0, true);
  if (lookAhead != std::floor(lookAhead) || lookAhead > 100000)
    bad(origin, "\"look_ahead_blocks\" must be a whole number up to 100000");
  m.lookAheadBlocks = static_cast<int>(lookAhead);
  m.cornerTolerance = number(root, "corner_tolerance_mm", origin, 1.0, false);
  m.jerkLimitedByDefault = flag(root, "jerk_limited_by_default", origin, m.controller == ControllerKind::Siemens840D);
  if (root.contains("arc_tolerance_mm")) m.arcTolerance = number(root, "arc_tolerance_mm", origin, 1.0, true);
  if (root.contains("compressor_path_limit_mm"))
    m.compressorPathLimit = number(root, "compressor_path_limit_mm", origin, 1.0, true);
  if (root.contains("rotary_axes")) {
    if (!root["rotary_axes"].is_array()) bad(origin, "\"rotary_axes\" must be a list of axes (see docs/machines.md)");
    for (const json& node : root["rotary_axes"]) m.rotaryAxes.push_back(rotaryAxis(node, origin));
  }
  if (root.contains("tool_axis")) {
    m.toolAxis = vector3(root, "tool_axis", origin);
    if (m.toolAxis.norm() < 1e-9) bad(origin, "\"tool_axis\" must not be zero");
    m.toolAxis.normalize();
  }
  m.toolTipProgrammed =
      m.hasRotaryAxes() && flag(root, "tool_tip_programmed", origin, m.controller == ControllerKind::LinuxCNC);
  m.rotaryPlanner = rotaryPlanner(root, m, origin);
  m.conventions = conventions(root, m.controller, origin);
  m.conventions.smoothingTolerance = m.cornerTolerance;
  if (root.contains("kinematics")) {
    const std::string said = root["kinematics"].is_string() ? root["kinematics"].get<std::string>() : "?";
    if (said != m.kinematicsName())
      bad(origin, "\"kinematics\": \"" + said + "\" but the rotary axes make a \"" + m.kinematicsName() +
                      "\" machine (head axes first, as the trade names it): correct one or the other");
  }
  try {
    checkMachine(m);
  } catch (const InputError& error) {
    bad(origin, error.what());
  }
  return m;
}

std::string machineToJson(const MachineModel& m) {
  json axes;
  for (int i = 0; i < 3; ++i)
    axes[kAxes[i]] = {{"max_velocity_mm_min", m.maxVelocity[i] * 60.0},
                      {"max_acceleration_m_s2", m.maxAcceleration[i] / kMetres},
                      {"max_jerk_m_s3", m.maxJerk[i] / kMetres},
                      {"rapid_velocity_mm_min", m.rapidVelocity[i] * 60.0},
                      {"velocity_jump_mm_min", m.velocityJump[i] * 60.0}};
  json root = {{"name", m.name},
               {"description", m.description},
               {"controller", controllerName(m.controller)},
               {"axes", axes},
               {"interpolation_cycle_ms", m.interpolationCycle * 1e3},
               {"look_ahead_blocks", m.lookAheadBlocks},
               {"corner_tolerance_mm", m.cornerTolerance},
               {"jerk_limited_by_default", m.jerkLimitedByDefault},
               {"arc_tolerance_mm", m.arcTolerance},
               {"compressor_path_limit_mm", m.compressorPathLimit}};
  root["dialect"] = dialectName(m.conventions.dialect);
  if (!m.conventions.powerOnCodes.empty()) root["power_on_codes"] = m.conventions.powerOnCodes;
  root["decimal_point"] = m.conventions.leastIncrementInput ? "least-increment" : "whole-units";
  const Eigen::Vector3d& offset = m.conventions.workOffset;
  root["work_offset_mm"] = {offset.x(), offset.y(), offset.z()};
  if (m.hasRotaryAxes()) {
    root["kinematics"] = m.kinematicsName();
    root["tool_axis"] = {m.toolAxis.x(), m.toolAxis.y(), m.toolAxis.z()};
    root["tool_tip_programmed"] = m.toolTipProgrammed;
    root["planner"] = rotaryPlannerName(m.rotaryPlanner);
    json axes = json::array();
    for (const RotaryAxis& a : m.rotaryAxes) axes.push_back(rotaryAxisJson(a));
    root["rotary_axes"] = axes;
  }
  return root.dump(2);
}

std::vector<std::string> machineNames(const std::vector<std::string>& folders) {
  std::vector<std::string> names;
  for (const auto& folder : folders) {
    std::error_code ignored;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ignored))
      if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

MachineModel loadMachine(const std::string& nameOrFile, const std::vector<std::string>& folders) {
  namespace fs = std::filesystem;
  fs::path path(nameOrFile);
  if (!fs::is_regular_file(path)) {
    path.clear();
    for (const auto& folder : folders)
      if (fs::is_regular_file(fs::path(folder) / (nameOrFile + ".json"))) {
        path = fs::path(folder) / (nameOrFile + ".json");
        break;
      }
  }
  if (path.empty()) {
    std::string known;
    for (const auto& name : machineNames(folders)) known += (known.empty() ? "" : ", ") + name;
    throw InputError("machine '" + nameOrFile + "' is neither a file nor a known machine: use one of " +
                     (known.empty() ? std::string("(none found)") : known) + ", or the path of a machine JSON file");
  }
  std::ifstream stream(path);
  std::stringstream text;
  text << stream.rdbuf();
  return machineFromJson(text.str(), path.string());
}

}  // namespace hsm::kinematics
