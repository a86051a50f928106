#include "roughing/clearance.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/tool_distance.hpp"
#include "roughing/triangle_grid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {
constexpr long kMaxPositions = 2000000;  // about 1 ms each on the impeller: bounded work

}  // namespace

struct ClearanceChecker::Impl {
  Impl(const TopoDS_Shape& part, double deflection)
      : deflection(deflection), mesh(geometry::meshFaces(part, deflection)), grid(mesh, kCell) {}
  static constexpr double kCell = 4.0;  // mm: the grid's cubes
  double deflection;
  geometry::TriangleMesh mesh;
  TriangleGrid grid;
};

ClearanceChecker::ClearanceChecker(const TopoDS_Shape& part, double deflection) {
  if (!(deflection >= 0.001 && deflection <= 1.0))
    throw InputError("clearance check: deflection " + number(deflection) + " mm is outside [0.001, 1] mm");
  impl_ = std::make_unique<Impl>(part, deflection);
}

ClearanceChecker::~ClearanceChecker() = default;

ClearanceReport ClearanceChecker::check(const std::vector<ToolMove>& moves, const Cutter& cutter, double limit,
                                        double spacing) const {
  checkCutter(cutter);
  if (!(spacing >= 0.01 && spacing <= 100.0))
    throw InputError("clearance check: spacing " + number(spacing) + " mm is outside [0.01, 100] mm");
  long total = static_cast<long>(moves.size());
  // Samples of a move: every `spacing` mm of the tip's path or of the holder's end's, whichever is more (a
  // 5-axis move turns the axis as it goes).
  auto samplesOf = [&](size_t i) {
    const double turn = std::acos(std::clamp(moves[i].axis.normalized().dot(moves[i - 1].axis.normalized()), -1.0, 1.0));
    return 1 + static_cast<long>(std::max((moves[i].tip - moves[i - 1].tip).norm(), turn * cutter.stickOut) / spacing);
  };
  for (size_t i = 1; i < moves.size(); ++i) {
    total += samplesOf(i) - 1;
    if (total > kMaxPositions)
      throw InputError("clearance check: more than " + std::to_string(kMaxPositions) + " positions at " + number(spacing) +
                       " mm: use a larger spacing");
  }
  const geometry::TriangleMesh& mesh = impl_->mesh;
  const double deflection = impl_->deflection;
  const CutterBody body(cutter, cutter.stickOut);
  const double reach = std::max(limit, 0.0) + 2.0;  // triangles farther than this from the tool do not matter
  std::vector<int> seen(mesh.triangles.size(), -1);
  int stamp = 0;
  ClearanceReport report;
  report.minimum = std::numeric_limits<double>::infinity();
  report.moveMinimum.assign(moves.size(), reach);
  Eigen::Vector3d local[3];
  auto checkAt = [&](const Eigen::Vector3d& tip, const Eigen::Vector3d& axis, int move) {
    const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
    double least = reach;
    impl_->grid.near(tip - axis * reach, tip + axis * cutter.stickOut, cutter.radius() + reach, seen, stamp++, [&](int t) {
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d d = mesh.vertices[mesh.triangles[t][k]] - tip;
        local[k] = Eigen::Vector3d(u.dot(d), v.dot(d), axis.dot(d));
      }
      // Quick rejections: wholly above the stick-out, or farther under the tip than the least distance yet.
      if (std::min({local[0].z(), local[1].z(), local[2].z()}) > cutter.stickOut) return;
      if (std::max({local[0].z(), local[1].z(), local[2].z()}) < -least) return;
      least = std::min(least, cutterDistance(local, body));
    });
    least -= deflection;
    report.moveMinimum[move] = std::min(report.moveMinimum[move], least);
    ++report.positions;
    if (least < limit) ++report.tooClose;
    if (least < report.minimum) {
      report.minimum = least;
      report.worstMove = move;
      report.worstTip = tip;
    }
  };
  // Along a move the tip goes straight and the axis turns evenly between its ends (as a controller's
  // orientation interpolation does between the ends' vectors).
  for (size_t i = 0; i < moves.size(); ++i) {
    const Eigen::Vector3d from = i > 0 ? moves[i - 1].tip : moves[i].tip;
    const Eigen::Vector3d fromAxis = i > 0 ? moves[i - 1].axis.normalized() : moves[i].axis.normalized();
    const long samples = i > 0 ? samplesOf(i) : 1;
    for (long k = 1; k <= samples; ++k) {
      const double f = double(k) / double(samples);
      const Eigen::Vector3d axis = ((1.0 - f) * fromAxis + f * moves[i].axis.normalized()).normalized();
      checkAt(from + (moves[i].tip - from) * f, axis, static_cast<int>(i));
    }
  }
  return report;
}

ClearanceReport checkClearance(const std::vector<ToolMove>& moves, const TopoDS_Shape& part, const Cutter& cutter,
                               double limit, double spacing, double deflection) {
  return ClearanceChecker(part, deflection).check(moves, cutter, limit, spacing);
}

}  // namespace hsm::roughing
