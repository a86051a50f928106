#include "toolpath/finishing_context.hpp"
#include "geometry/bounds.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"
#include "geometry/face_drop.hpp"
#include "geometry/mesh.hpp"
#include "toolpath/reach.hpp"

#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <thread>

namespace hsm::toolpath::detail {

namespace {
void checkRange(double value, double low, double high, const std::string& what, const std::string& hint) {
  if (!(value >= low && value <= high))
    throw InputError(what + " " + mm(value) + " is outside [" + number(low) + ", " + number(high) + "] mm: " + hint);
}

// Holes a pass bridges in one straight move, as a share of the tool radius (see finishing.hpp).
constexpr double kBridgeRadii = 10.0;
}  // namespace

void validate(const FinishingSettings& s) {
  checkRange(2.0 * s.toolRadius, 2.0 * kMinToolRadius, 2.0 * kMaxToolRadius, "tool diameter",
             "ball-end mills for finishing are 0.1 to 100 mm (the paper's is 4 mm)");
  if (!(s.cuspHeight >= kMinCuspHeight && s.cuspHeight < s.toolRadius))
    throw InputError("cusp height " + mm(s.cuspHeight) + " must be at least " + mm(kMinCuspHeight) +
                     " (below any machine's repeatability) and below the tool radius " + mm(s.toolRadius) +
                     ": the paper uses 0.01 mm");
  checkRange(s.tolerance, kMinTolerance, kMaxTolerance, "machining tolerance", "the paper uses 0.01 mm");
  checkRange(s.sampling, kMinSampling, s.toolRadius, "sampling", "cutter positions every 0.25 mm by default");
  checkRange(s.clearance, 0.0, kMaxClearance, "clearance", "rapids run this far above the part, e.g. 5 mm");
  checkRange(s.meshDeflection, 1e-3, 1.0, "mesh deflection", "0.004 mm by default");
  if (!(s.meshSeconds > 0.0 && s.meshSeconds <= 3600.0))
    throw InputError("mesh time limit " + std::to_string(s.meshSeconds) + " s must be in ]0, 3600] s (" +
                     std::to_string(static_cast<int>(geometry::kMeshSeconds)) + " s by default)");
  if (!(s.extension <= 10.0 * s.toolRadius) || std::isnan(s.extension))
    throw InputError("extension " + mm(s.extension) + " past open boundaries must be at most ten tool radii (" +
                     mm(10.0 * s.toolRadius) + "); a negative value means the tool radius");
  checkThreads(s.threads, "finishing");
}

std::string faceName(int index) { return "Face" + std::to_string(index); }

Context::Context(const TopoDS_Shape& part, int bottomFace, const FinishingSettings& settings)
    : settings_(settings), bottomFace_(bottomFace), progress_(settings.progress, "finishing") {
  validate(settings);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(part, TopAbs_FACE, faces);
  if (bottomFace < 1 || bottomFace > faces.Extent())
    throw InputError("bottom face " + faceName(bottomFace) + " does not exist: the part has " +
                     std::to_string(faces.Extent()) + " faces (Face1 to Face" + std::to_string(faces.Extent()) + ")");
  bottom_ = TopoDS::Face(faces(bottomFace));
  const Reach reach = reachability(bottom_);
  const std::string partly = checkReach(reach, faceName(bottomFace));
  if (!partly.empty()) warnings.push_back(partly);
  // Every face of the part that the ball can meet above the bottom face holds the tool up (a pass must
  // not cut through the part to reach it); faces beyond the tool's reach in plan are left out. The bottom
  // face itself is dropped on exactly, and meshed too where part of it looks down.
  Bnd_Box reachBox = geometry::exactBounds(bottom_);
  reachBox.Enlarge(settings.toolRadius + std::max(settings.extension, settings.toolRadius) + 1.0);
  reachBox.OpenZmin();  // in plan only: a face far above (a shelf) or below still holds the tool
  reachBox.OpenZmax();
  std::vector<int> others;
  for (int i = 1; i <= faces.Extent(); ++i) {
    Bnd_Box faceBox = geometry::exactBounds(faces(i));
    const bool nearInPlan = !faceBox.IsVoid() && !reachBox.IsOut(faceBox);
    if ((i != bottomFace || reach.up < 1.0) && nearInPlan) others.push_back(i);
  }
  geometry::TriangleMesh mesh =
      others.empty() ? geometry::TriangleMesh{} : geometry::meshFacesKept(part, settings.meshDeflection, others,
                                                                     settings.meshSeconds);
  geometry::addFaceBoundary(mesh, part, bottomFace, 0.05);
  cutter_ = std::make_unique<BallDropCutter>(mesh, settings.toolRadius);
  exact_ = std::make_unique<SurfaceBallDrop>(bottom_, settings.toolRadius, reach.toolSide);
  gauge_ = std::make_unique<CuspGauge>(*exact_, settings.toolRadius);
  Bnd_Box box = geometry::exactBounds(part);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  safeHeight_ = z1 + settings.clearance;
  Bnd_Box faceBox = geometry::exactBounds(bottom_);
  faceBox.Get(x0, y0, z0, x1, y1, z1);
  faceMin_ = Vector2(x0, y0);
  faceMax_ = Vector2(x1, y1);
  extension_ = settings.extension >= 0.0 ? settings.extension : settings.toolRadius;
}

void Context::checkWork(double width, double length) const {
  const double passes = width / flatStep() + 1.0, perPass = length / settings_.sampling + 1.0;
  if (passes > double(kMaxPasses)) {
    const double step = width / double(kMaxPasses), r = settings_.toolRadius;
    throw InputError("cusp height " + mm(settings_.cuspHeight) + " with a " + mm(2.0 * r) + " ball gives a " +
                     "stepover of " + mm(flatStep()) + ": about " + number(std::round(passes)) + " passes over the " +
                     mm(width) + " of " + faceName(bottomFace_) + " (the limit is " + std::to_string(kMaxPasses) +
                     "): use a cusp height of at least " + mm(step * step / (8.0 * r)));
  }
  if (passes * perPass > kMaxPlanPoints)
    throw InputError("about " + number(passes * perPass) + " cutter positions (" + number(std::round(passes)) +
                     " passes of " + mm(length) + " sampled every " + mm(settings_.sampling) + ") exceed the limit " +
                     number(kMaxPlanPoints) + ": use a larger cusp height or sampling, or split the face");
}

double Context::dropTip(double x, double y, SurfaceBallDrop::Result& state, bool& haveGuess,
                        bool* onBottom) const {
  double z = cutter_->drop(x, y).z;
  SurfaceBallDrop::Result r = state;
  bool bottomHolds = false;
  if (exact_->drop(x, y, r, haveGuess)) {
    state = r;
    haveGuess = true;
    if (r.onFace) {
      bottomHolds = r.tipZ >= z - 1e-9;
      z = std::max(z, r.tipZ);
    }
  } else {
    haveGuess = false;
  }
  if (onBottom) *onBottom = bottomHolds;
  return z;
}

void Context::dropAll(geometry::PointArray& points, std::vector<char>& onBottom, int threads) const {
  onBottom.assign(static_cast<size_t>(points.rows()), 0);
  // chunks taken in turn: a point costs what the surface under it asks (a warm start saves most; a fillet not)
  parallelChunks(static_cast<long>(points.rows()), threads < 0 ? settings_.threads : threads, 500, [&](long from, long to) {
    SurfaceBallDrop::Result state;
    bool haveGuess = false;
    for (Eigen::Index i = from; i < to; ++i) {
      bool bottom = false;
      points(i, 2) = dropTip(points(i, 0), points(i, 1), state, haveGuess, &bottom);
      onBottom[static_cast<size_t>(i)] = bottom;
    }
  });
}

double Context::flatStep() const {
  const double r = settings_.toolRadius, h = settings_.cuspHeight;
  return 2.0 * std::sqrt(2.0 * r * h - h * h);
}

double Context::tipAt(double x, double y) const {
  SurfaceBallDrop::Result state;
  bool haveGuess = false;
  return dropTip(x, y, state, haveGuess);
}

std::vector<Pass> Context::cut(const std::vector<Vector2>& plan, int threads) const {
  std::vector<Pass> passes;
  if (plan.size() < 2) return passes;
  geometry::PointArray points(static_cast<Eigen::Index>(plan.size()), 3);
  for (size_t i = 0; i < plan.size(); ++i) points.row(static_cast<Eigen::Index>(i)) << plan[i].x(), plan[i].y(), 0.0;
  std::vector<char> onBottom;
  dropAll(points, onBottom, threads);
  dropped += points.rows();
  // Runs of positions where the ball rests on the bottom face; where a flank holds it up the run ends
  // (it would only ride up the wall).
  std::vector<std::pair<size_t, size_t>> runs;
  for (size_t i = 0; i < plan.size();) {
    while (i < plan.size() && !onBottom[i]) ++i;
    if (i == plan.size()) break;
    size_t j = i;
    while (j + 1 < plan.size() && onBottom[j + 1]) ++j;
    runs.emplace_back(i, j);
    i = j + 1;
  }
  // Runs joined across the holes the tool bridges make one pass; each pass is extended past its open
  // ends (where nothing lifts the tool) and refined within the tolerance.
  for (size_t r = 0; r < runs.size();) {
    size_t last = r;
    while (last + 1 < runs.size() && bridges(points, plan, runs[last].second, runs[last + 1].first)) ++last;
    std::vector<size_t> indices;
    for (size_t k = extend(points, plan, runs[r].first, -1); k <= runs[r].second; ++k) indices.push_back(k);
    for (size_t q = r + 1; q <= last; ++q) {
      const size_t to = q == last ? extend(points, plan, runs[q].second, +1) : runs[q].second;
      for (size_t k = runs[q].first; k <= to; ++k) indices.push_back(k);
    }
    if (r == last) {
      const size_t to = extend(points, plan, runs[r].second, +1);
      for (size_t k = runs[r].second + 1; k <= to; ++k) indices.push_back(k);
    }
    Pass pass = refine(points, indices);
    if (pass.size() >= 2) passes.push_back(simplify(pass));
    r = last + 1;
  }
  return passes;
}

void Context::bisect(const Vector3& a, const Vector3& b, int depth, Pass& out, SurfaceBallDrop::Result& state,
                     bool& haveGuess, const std::function<double(const Vector2&)>& floor) const {
  const Vector2 mid = 0.5 * (a.head<2>() + b.head<2>());
  double z = dropTip(mid.x(), mid.y(), state, haveGuess);
  ++dropped;
  if (floor) z = std::max(z, floor(mid));
  if (!std::isfinite(z)) return;
  const Vector3 m(mid.x(), mid.y(), z);
  if (depth < 8 && std::abs(z - 0.5 * (a.z() + b.z())) > 0.25 * settings_.tolerance) {
    bisect(a, m, depth + 1, out, state, haveGuess, floor);
    out.push_back(m);
    bisect(m, b, depth + 1, out, state, haveGuess, floor);
  }
}

bool Context::bridges(const geometry::PointArray& points, const std::vector<Vector2>& plan, size_t from, size_t to) const {
  const double span = (plan[to] - plan[from]).norm();
  if (span > kBridgeRadii * settings_.toolRadius) return false;
  const double z0 = points(static_cast<Eigen::Index>(from), 2), z1 = points(static_cast<Eigen::Index>(to), 2);
  for (size_t k = from + 1; k < to; ++k) {
    const double f = span > 0.0 ? (plan[k] - plan[from]).norm() / span : 0.0;
    const double z = points(static_cast<Eigen::Index>(k), 2);
    if (z > z0 + f * (z1 - z0) + 0.5 * settings_.tolerance) return false;  // a wall or an island, not a hole
  }
  return true;
}

size_t Context::extend(const geometry::PointArray& points, const std::vector<Vector2>& plan, size_t end, int step) const {
  const double zEnd = points(static_cast<Eigen::Index>(end), 2);
  size_t k = end;
  while (true) {
    const long next = static_cast<long>(k) + step;
    if (next < 0 || next >= static_cast<long>(plan.size())) break;
    if ((plan[static_cast<size_t>(next)] - plan[end]).norm() > extension_ + 1e-9) break;
    const double z = points(next, 2);
    if (!std::isfinite(z) || z > zEnd + settings_.tolerance) break;  // a wall, or nothing at all
    k = static_cast<size_t>(next);
  }
  return k;
}

Pass Context::refine(const geometry::PointArray& points, const std::vector<size_t>& indices) const {
  Pass pass;
  SurfaceBallDrop::Result state;  // carried from one midpoint to the next: they are neighbours
  bool haveGuess = false;
  for (size_t n = 0; n < indices.size(); ++n) {
    const Eigen::Index k = static_cast<Eigen::Index>(indices[n]);
    const Vector3 p(points(k, 0), points(k, 1), points(k, 2));
    if (!std::isfinite(p.z())) continue;
    const bool bridge = n > 0 && indices[n] > indices[n - 1] + 1;  // straight across a hole
    if (!pass.empty() && !bridge) bisect(pass.back(), p, 0, pass, state, haveGuess);
    pass.push_back(p);
  }
  return pass;
}

Pass Context::simplify(const Pass& pass) const {
  const double tolerance = 0.75 * settings_.tolerance;
  std::vector<char> keep(pass.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<size_t, size_t>> stack{{0, pass.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const Vector3 d = pass[b] - pass[a];
    const double length = d.norm();
    double worst = 0.0;
    size_t at = a;
    for (size_t k = a + 1; k < b; ++k) {
      const Vector3 w = pass[k] - pass[a];
      const double distance = length > 0 ? (w - (w.dot(d) / (length * length)) * d).norm() : w.norm();
      if (distance > worst) {
        worst = distance;
        at = k;
      }
    }
    if (worst > tolerance) {
      keep[at] = 1;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
  Pass result;
  for (size_t k = 0; k < pass.size(); ++k)
    if (keep[k]) result.push_back(pass[k]);
  return result;
}

}  // namespace hsm::toolpath::detail
