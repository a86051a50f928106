// The context every finishing strategy works in (internal): the part meshed for the drop-cutter, the exact
// drop on the bottom face, the cusp gauge, the checks of the settings and of the work they ask for, and
// the cutting of one plan polyline into refined passes.
#pragma once

#include "common/progress.hpp"
#include "geometry/points.hpp"
#include "toolpath/cusp.hpp"
#include "toolpath/dropcutter.hpp"
#include "toolpath/finishing.hpp"
#include "toolpath/surface_drop.hpp"

#include <TopoDS_Face.hxx>

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace hsm::toolpath::detail {

using Vector2 = Eigen::Vector2d;
using Vector3 = Eigen::Vector3d;
using Pass = std::vector<Vector3>;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Refuses settings outside the limits of finishing.hpp, naming the setting and its range.
void validate(const FinishingSettings& settings);
std::string faceName(int index);

// What every strategy needs: the part meshed for the drop-cutter, the bottom face for contact points.
class Context {
public:
  Context(const TopoDS_Shape& part, int bottomFace, const FinishingSettings& settings);

  // Refuses settings that would need more passes or cutter positions than the limits, before any is
  // computed: `width` across the passes, `length` of one pass (mm).
  void checkWork(double width, double length) const;

  // Reports the share done; throws Cancelled when the user stops.
  void report(double done) { progress_(done); }
  std::vector<std::string> warnings;

  const FinishingSettings& settings() const { return settings_; }
  const CuspGauge& gauge() const { return *gauge_; }

  // The tool tip at (x, y): the highest of the exact contact on the bottom face and the mesh contacts.
  // `state` carries the surface parameters from one point to the next along a pass.
  double dropTip(double x, double y, SurfaceBallDrop::Result& state, bool& haveGuess, bool* onBottom = nullptr) const;

  // Tips along plan points, on `threads` threads (-1: the settings'; each chunk starts its own Newton).
  void dropAll(geometry::PointArray& points, std::vector<char>& onBottom, int threads = -1) const;
  // The stepover on a flat face.
  double flatStep() const;
  double safeHeight() const { return safeHeight_; }
  double tipAt(double x, double y) const;
  Vector2 faceMin() const { return faceMin_; }
  Vector2 faceMax() const { return faceMax_; }
  // Cutter positions computed (for the figures): counted from the threads that cut passes side by side.
  mutable std::atomic<long> dropped{0};

  // Cutter passes along a plan polyline: dropped (on `threads` threads, -1: the settings'), kept over the
  // bottom face (extended past open ends), refined within the tolerance and reduced to G1 points. A polyline
  // may give several passes. Safe to call from several threads at once (passes cut side by side).
  std::vector<Pass> cut(const std::vector<Vector2>& plan, int threads = -1) const;

  // Points between a and b where the path bends more than a quarter of the tolerance off the chord, by
  // bisection (at most 8 levels): the tip dropped at each midpoint, raised to `floor` there if given.
  void bisect(const Vector3& a, const Vector3& b, int depth, Pass& out, SurfaceBallDrop::Result& state,
              bool& haveGuess, const std::function<double(const Vector2&)>& floor = {}) const;

private:
  // The gap between positions `from` and `to` (the ball off the face in between) is a hole the tool
  // bridges: short enough, and nothing in it stands above the straight line between its rims.
  bool bridges(const geometry::PointArray& points, const std::vector<Vector2>& plan, size_t from, size_t to) const;

  size_t extend(const geometry::PointArray& points, const std::vector<Vector2>& plan, size_t end, int step) const;

  Pass refine(const geometry::PointArray& points, const std::vector<size_t>& indices) const;

  // Douglas-Peucker: the fewest points within 3/4 of the tolerance of the refined polyline.
  Pass simplify(const Pass& pass) const;

  FinishingSettings settings_;
  int bottomFace_;
  ProgressReporter progress_;
  TopoDS_Face bottom_;
  std::unique_ptr<BallDropCutter> cutter_;
  std::unique_ptr<SurfaceBallDrop> exact_;
  std::unique_ptr<CuspGauge> gauge_;
  double safeHeight_ = 0.0, extension_ = 0.0;
  Vector2 faceMin_, faceMax_;
};

}  // namespace hsm::toolpath::detail
