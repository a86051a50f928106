// An independent clearance check of a roughing toolpath against the finished part: how close the tool comes,
// everywhere along the moves, measured on the part's own triangles (not on the sweep's shadows and offsets).
//
// The tool is the cutter as it is, up its axis over the stick-out, its distance to each triangle exact
// (tool_distance.hpp); the sweep keeps the part away with shadows and offsets, not with this distance, except
// where it pushes a level's boundary out to the real clearance.
// The part's triangles are within `deflection` of its surfaces: the report subtracts it.
#pragma once

#include "roughing/sweep.hpp"

#include <TopoDS_Shape.hxx>

#include <memory>
#include <vector>

namespace hsm::roughing {

struct ClearanceReport {
  double minimum = 0.0;           // mm: the least distance from the tool to the part over all positions checked
  long positions = 0;             // tool positions checked
  long tooClose = 0;              // positions closer than the limit asked
  int worstMove = -1;             // index of the move where the least distance is
  Eigen::Vector3d worstTip = Eigen::Vector3d::Zero();
  // Per move, the least distance along it (capped at the limit + 2 mm: farther triangles are not looked at).
  std::vector<double> moveMinimum;
};

// The part's triangles (within `deflection`) in a grid, built once for any number of toolpaths.
class ClearanceChecker {
public:
  // InputError for a deflection outside 0.001–1 mm.
  ClearanceChecker(const TopoDS_Shape& part, double deflection = 0.01);
  ~ClearanceChecker();
  ClearanceChecker(const ClearanceChecker&) = delete;
  ClearanceChecker& operator=(const ClearanceChecker&) = delete;

  // The moves (rapids too: a rapid must not hit the part either) sampled every `spacing` mm; `limit` counts the
  // positions closer than it (e.g. the allowance − 0.01 mm). InputError for a spacing outside 0.01–100 mm, and
  // when the moves would need more than 2 million positions.
  ClearanceReport check(const std::vector<ToolMove>& moves, const Cutter& cutter, double limit,
                        double spacing = 1.0) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One toolpath checked against `part`: ClearanceChecker(part, deflection).check(moves, cutter, limit, spacing).
ClearanceReport checkClearance(const std::vector<ToolMove>& moves, const TopoDS_Shape& part, const Cutter& cutter,
                               double limit, double spacing = 1.0, double deflection = 0.01);

}  // namespace hsm::roughing
