#include "kinematics/five_axis.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::kinematics {

namespace {
constexpr double kDegree = M_PI / 180.0;

// Rodrigues' formula with one sincos: the simulator turns every block's axes through it.
Eigen::Matrix3d rotation(const RotaryAxis& axis, double degrees) {
  const double angle = degrees * kDegree, s = std::sin(angle), c = std::cos(angle), k = 1.0 - c;
  const Eigen::Vector3d& w = axis.direction;
  Eigen::Matrix3d r;
  r << c + k * w.x() * w.x(), k * w.x() * w.y() - s * w.z(), k * w.x() * w.z() + s * w.y(),
      k * w.y() * w.x() + s * w.z(), c + k * w.y() * w.y(), k * w.y() * w.z() - s * w.x(),
      k * w.z() * w.x() - s * w.y(), k * w.z() * w.y() + s * w.x(), c + k * w.z() * w.z();
  return r;
}

// The rigid motion of the table (workpiece -> machine) or of the head (tip frame -> carriage), composed from the
// first axis of the part outwards: x -> R x + t.
struct Motion {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  bool identity = true;
  void then(const RotaryAxis& axis, double degrees) {  // this ∘ (turn about the axis through its pivot)
    const Eigen::Matrix3d r = rotation(axis, degrees);
    const Eigen::Vector3d shift = axis.pivot - r * axis.pivot;
    if (identity) {  // the first turn of the chain: nothing to compose with
      t = shift;
      R = r;
      identity = false;
      return;
    }
    t += R * shift;
    R = R * r;
  }
};

Motion chainMotion(const MachineModel& m, const RotaryAngles& angles, bool table) {
  Motion motion;
  for (size_t i = 0; i < m.rotaryAxes.size(); ++i)
    if (m.rotaryAxes[i].onTable == table) motion.then(m.rotaryAxes[i], angles[i]);
  return motion;
}

// Angle (deg) that turns u about the unit axis w onto z, both taken in the plane normal to w; free when u
// lies on the axis (any angle does).
double angleAbout(const Eigen::Vector3d& w, const Eigen::Vector3d& u, const Eigen::Vector3d& z, bool& free) {
  const Eigen::Vector3d a = u - w * w.dot(u), b = z - w * w.dot(z);
  free = a.norm() < 1e-9 || b.norm() < 1e-9;
  if (free) return 0.0;
  return std::atan2(w.dot(a.cross(b)), a.dot(b)) / kDegree;
}

double wrap180(double degrees) {
  double a = std::remainder(degrees, 360.0);
  return a <= -180.0 ? a + 360.0 : a;
}

// The orientation equation in the form R(ωL, sL·θL) u = R(ωR, sR·θR) v, one rotation on each side (see the
// header): which axis is on each side, with which sign, turning which vector.
struct Sides {
  int left = -1, right = -1;       // indices in rotaryAxes (−1: no rotation on that side)
  double leftSign = 1.0, rightSign = 1.0;
};

Sides sides(const MachineModel& m) {
  const auto& axes = m.rotaryAxes;
  Sides s;
  if (axes.size() == 1) {
    if (axes[0].onTable) s.left = 0;    // R(θ) d_w = d0
    else s.right = 0;                   // d_w = R(θ) d0
  } else if (axes[0].onTable && axes[1].onTable) {
    s.left = 1;                          // R₂(θ₂) d_w = R₁(−θ₁) d0
    s.right = 0, s.rightSign = -1.0;
  } else if (axes[0].onTable) {
    s.left = 0, s.right = 1;             // R_table(θ) d_w = R_head(φ) d0
  } else {
    s.left = 0, s.leftSign = -1.0;       // R₁(−φ₁) d_w = R₂(φ₂) d0
    s.right = 1;
  }
  return s;
}

[[noreturn]] void unreachable(const MachineModel& m, const Eigen::Vector3d& axis) {
  throw InputError("machine \"" + m.name + "\" (" + m.kinematicsName() + ") cannot point the tool along (" +
                   hsm::number(axis.x()) + ", " + hsm::number(axis.y()) + ", " + hsm::number(axis.z()) +
                   "): no angles of its rotary axes give that orientation");
}
}  // namespace

ToolPose forwardKinematics(const MachineModel& m, const MachinePosition& position) {
  if (!position.linear.allFinite() || !std::isfinite(position.angles[0]) || !std::isfinite(position.angles[1]))
    throw InputError("forward kinematics: the machine position must be finite numbers (mm, deg)");
  const Motion table = chainMotion(m, position.angles, true), head = chainMotion(m, position.angles, false);
  ToolPose pose;
  // machine tip = X Y Z + head(0); workpiece point = table⁻¹(machine point)
  const Eigen::Vector3d machineTip = position.linear + head.t;
  pose.tip = table.R.transpose() * (machineTip - table.t);
  pose.axis = table.R.transpose() * (head.R * m.toolAxis);
  return pose;
}

Eigen::Vector3d toolAxisAt(const MachineModel& m, const RotaryAngles& angles) {
  const Motion table = chainMotion(m, angles, true), head = chainMotion(m, angles, false);
  return table.R.transpose() * (head.R * m.toolAxis);
}

namespace {
// The point x turned by `degrees` about the axis through its pivot (Rodrigues on the vector itself).
Eigen::Vector3d turned(const RotaryAxis& axis, double degrees, const Eigen::Vector3d& x) {
  const double angle = degrees * kDegree, s = std::sin(angle), c = std::cos(angle);
  const Eigen::Vector3d& w = axis.direction;
  const Eigen::Vector3d v = x - axis.pivot;
  return axis.pivot + c * v + s * w.cross(v) + ((1.0 - c) * w.dot(v)) * w;
}

// chainMotion(m, angles, table) applied to x, the outermost axis first: no matrices composed.
Eigen::Vector3d chainPoint(const MachineModel& m, const RotaryAngles& angles, bool table, Eigen::Vector3d x) {
  for (size_t i = m.rotaryAxes.size(); i-- > 0;)
    if (m.rotaryAxes[i].onTable == table) x = turned(m.rotaryAxes[i], angles[i], x);
  return x;
}
}  // namespace

// The simulator asks this for every block of a 5-axis program: the point alone, turned axis by axis.
Eigen::Vector3d linearAxesFor(const MachineModel& m, const Eigen::Vector3d& tip, const RotaryAngles& angles) {
  return chainPoint(m, angles, true, tip) - chainPoint(m, angles, false, Eigen::Vector3d::Zero());
}

std::vector<AngleSolution> orientationSolutions(const MachineModel& m, const Eigen::Vector3d& wanted) {
  std::vector<AngleSolution> result;
  if (!(wanted.allFinite() && wanted.norm() > 1e-12)) return result;
  const Eigen::Vector3d u = wanted.normalized(), v = m.toolAxis;
  const Sides s = sides(m);
  if (m.rotaryAxes.empty()) {
    if ((u - v).norm() <= kOrientationTolerance) result.push_back({});
    return result;
  }
  if (m.rotaryAxes.size() == 1) {
    // One rotation: u and v must lie on one cone about the axis.
    const int i = s.left >= 0 ? s.left : s.right;
    const Eigen::Vector3d& w = m.rotaryAxes[i].direction;
    if (std::abs(w.dot(u) - w.dot(v)) > kOrientationTolerance) return result;
    AngleSolution solution;
    bool free = false;
    solution.angles[i] = wrap180(s.left >= 0 ? angleAbout(w, u, v, free) : angleAbout(w, v, u, free));
    solution.free[i] = free;
    result.push_back(solution);
    return result;
  }
  // Two rotations: z = R_L u = R_R v lies on both cones, ωL·z = ωL·u and ωR·z = ωR·v (Paden–Kahan 2).
  const Eigen::Vector3d& wl = m.rotaryAxes[s.left].direction;
  const Eigen::Vector3d& wr = m.rotaryAxes[s.right].direction;
  const double c = wl.dot(wr), al = wl.dot(u), ar = wr.dot(v);
  const double det = 1.0 - c * c;  // > 0: the axes are not parallel (checkMachine)
  const double a = (al - c * ar) / det, b = (ar - c * al) / det;
  const Eigen::Vector3d n = wl.cross(wr);
  const double inPlane = a * a + b * b + 2.0 * a * b * c;
  double g2 = (1.0 - inPlane) / n.squaredNorm();
  if (g2 < -kOrientationTolerance) return result;
  g2 = std::max(0.0, g2);
  const double g = std::sqrt(g2);
  for (double sign : {1.0, -1.0}) {
    if (sign < 0.0 && g < 1e-9) break;  // one double solution
    const Eigen::Vector3d z = (a * wl + b * wr + sign * g * n).normalized();
    AngleSolution solution;
    bool freeLeft = false, freeRight = false;
    solution.angles[s.left] = wrap180(s.leftSign * angleAbout(wl, u, z, freeLeft));
    solution.angles[s.right] = wrap180(s.rightSign * angleAbout(wr, v, z, freeRight));
    solution.free[s.left] = freeLeft;
    solution.free[s.right] = freeRight;
    result.push_back(solution);
  }
  return result;
}

InverseResult inverseKinematics(const MachineModel& m, const ToolPose& pose, const RotaryAngles& previous) {
  if (!pose.tip.allFinite() || !std::isfinite(previous[0]) || !std::isfinite(previous[1]))
    throw InputError("inverse kinematics: the tool tip and the previous angles must be finite numbers (mm, deg)");
  InverseResult result;
  const std::vector<AngleSolution> solutions = orientationSolutions(m, pose.axis);
  result.solutions = static_cast<int>(solutions.size());
  if (solutions.empty()) unreachable(m, pose.axis);
  const size_t n = m.rotaryAxes.size();
  double best = std::numeric_limits<double>::infinity();
  bool found = false;
  for (const AngleSolution& solution : solutions) {
    RotaryAngles angles = previous;
    bool inTravel = true;
    double change = 0.0;
    for (size_t i = 0; i < n; ++i) {
      const RotaryAxis& axis = m.rotaryAxes[i];
      if (solution.free[i]) continue;  // keeps its previous angle
      // The turn nearest to the previous angle, or the nearest within travel.
      const double nearest = solution.angles[i] + 360.0 * std::round((previous[i] - solution.angles[i]) / 360.0);
      double chosen = std::numeric_limits<double>::quiet_NaN();
      for (int k : {0, 1, -1, 2, -2}) {
        const double candidate = nearest + 360.0 * k;
        if (axis.continuous || (candidate >= axis.minPosition - 1e-9 && candidate <= axis.maxPosition + 1e-9)) {
          if (std::isnan(chosen) || std::abs(candidate - previous[i]) < std::abs(chosen - previous[i])) chosen = candidate;
        }
      }
      if (std::isnan(chosen)) {
        inTravel = false;
        break;
      }
      angles[i] = chosen;
      change += std::abs(chosen - previous[i]);
    }
    if (inTravel && change < best) {
      best = change;
      result.position.angles = angles;
      result.singular = solution.free[0] || (n > 1 && solution.free[1]);
      found = true;
    }
  }
  if (!found) {
    std::string travels;
    for (const RotaryAxis& axis : m.rotaryAxes)
      if (!axis.continuous)
        travels += std::string(travels.empty() ? "" : ", ") + axis.name + " [" + hsm::number(axis.minPosition) +
                   ", " + hsm::number(axis.maxPosition) + "] deg";
    throw InputError("machine \"" + m.name + "\": the tool axis (" + hsm::number(pose.axis.x()) + ", " +
                     hsm::number(pose.axis.y()) + ", " + hsm::number(pose.axis.z()) +
                     ") needs rotary angles outside the travel (" + travels + ")");
  }
  result.position.linear = linearAxesFor(m, pose.tip, result.position.angles);
  return result;
}

}  // namespace hsm::kinematics
