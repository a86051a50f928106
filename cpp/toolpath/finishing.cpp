#include "toolpath/finishing.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"
#include "geometry/plane_cutter.hpp"
#include "geometry/face_drop.hpp"
#include "toolpath/cusp.hpp"
#include "toolpath/reach.hpp"
#include "toolpath/surface_drop.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <thread>

namespace hsm::toolpath {

namespace {

using Vector2 = Eigen::Vector2d;
using Vector3 = Eigen::Vector3d;
using Pass = std::vector<Vector3>;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kStationStep = 1.0;  // mm between the points that decide the stepover

void checkRange(double value, double low, double high, const std::string& what, const std::string& hint) {
  if (!(value >= low && value <= high))
    throw InputError(what + " " + mm(value) + " is outside [" + number(low) + ", " + number(high) + "] mm: " + hint);
}

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
  if (!(s.extension <= 10.0 * s.toolRadius) || std::isnan(s.extension))
    throw InputError("extension " + mm(s.extension) + " past open boundaries must be at most ten tool radii (" +
                     mm(10.0 * s.toolRadius) + "); a negative value means the tool radius");
  if (s.threads < 0 || s.threads > 1024)
    throw InputError("threads " + std::to_string(s.threads) + " must be 0 (all cores) to 1024");
}

std::string faceName(int index) { return "Face" + std::to_string(index); }

// Holes a pass bridges in one straight move, as a share of the tool radius (see finishing.hpp).
constexpr double kBridgeRadii = 10.0;

// What every strategy needs: the part meshed for the drop-cutter, the bottom face for contact points.
class Context {
public:
  Context(const TopoDS_Shape& part, int bottomFace, const FinishingSettings& settings)
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
    Bnd_Box reachBox;
    BRepBndLib::AddOptimal(bottom_, reachBox, false, false);
    reachBox.Enlarge(settings.toolRadius + std::max(settings.extension, settings.toolRadius) + 1.0);
    reachBox.OpenZmin();  // in plan only: a face far above (a shelf) or below still holds the tool
    reachBox.OpenZmax();
    std::vector<int> others;
    for (int i = 1; i <= faces.Extent(); ++i) {
      Bnd_Box faceBox;
      BRepBndLib::Add(faces(i), faceBox);
      const bool nearInPlan = !faceBox.IsVoid() && !reachBox.IsOut(faceBox);
      if ((i != bottomFace || reach.up < 1.0) && nearInPlan) others.push_back(i);
    }
    geometry::TriangleMesh mesh = others.empty() ? geometry::TriangleMesh{} : geometry::meshFaces(part, settings.meshDeflection, others);
    geometry::addFaceBoundary(mesh, part, bottomFace, 0.05);
    cutter_ = std::make_unique<BallDropCutter>(mesh, settings.toolRadius);
    exact_ = std::make_unique<SurfaceBallDrop>(bottom_, settings.toolRadius, reach.toolSide);
    gauge_ = std::make_unique<CuspGauge>(*exact_, settings.toolRadius);
    Bnd_Box box;
    BRepBndLib::Add(part, box);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    safeHeight_ = z1 + settings.clearance;
    Bnd_Box faceBox;
    BRepBndLib::AddOptimal(bottom_, faceBox, false, false);
    faceBox.Get(x0, y0, z0, x1, y1, z1);
    faceMin_ = Vector2(x0, y0);
    faceMax_ = Vector2(x1, y1);
    extension_ = settings.extension >= 0.0 ? settings.extension : settings.toolRadius;
  }

  // Refuses settings that would need more passes or cutter positions than the limits, before any is
  // computed: `width` across the passes, `length` of one pass (mm).
  void checkWork(double width, double length) const {
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

  // Reports the share done; throws Cancelled when the user stops.
  void report(double done) { progress_(done); }
  std::vector<std::string> warnings;

  const FinishingSettings& settings() const { return settings_; }
  const CuspGauge& gauge() const { return *gauge_; }

  // The tool tip at (x, y): the highest of the exact contact on the bottom face and the mesh contacts.
  // `state` carries the surface parameters from one point to the next along a pass.
  double dropTip(double x, double y, SurfaceBallDrop::Result& state, bool& haveGuess, bool* onBottom = nullptr) const {
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

  // Tips along plan points, on the threads asked for (each slice of the pass starts its own Newton).
  void dropAll(geometry::PointArray& points, std::vector<char>& onBottom) const {
    onBottom.assign(static_cast<size_t>(points.rows()), 0);
    parallelSlices(static_cast<long>(points.rows()), settings_.threads, 500, [&](long from, long to) {
      SurfaceBallDrop::Result state;
      bool haveGuess = false;
      for (Eigen::Index i = from; i < to; ++i) {
        bool bottom = false;
        points(i, 2) = dropTip(points(i, 0), points(i, 1), state, haveGuess, &bottom);
        onBottom[static_cast<size_t>(i)] = bottom;
      }
    });
  }
  // The stepover on a flat face.
  double flatStep() const {
    const double r = settings_.toolRadius, h = settings_.cuspHeight;
    return 2.0 * std::sqrt(2.0 * r * h - h * h);
  }
  double safeHeight() const { return safeHeight_; }
  double tipAt(double x, double y) const {
    SurfaceBallDrop::Result state;
    bool haveGuess = false;
    return dropTip(x, y, state, haveGuess);
  }
  Vector2 faceMin() const { return faceMin_; }
  Vector2 faceMax() const { return faceMax_; }
  long dropped = 0;

  // Cutter passes along a plan polyline: dropped, kept over the bottom face (extended past open ends),
  // refined within the tolerance and reduced to G1 points. A polyline may give several passes.
  std::vector<Pass> cut(const std::vector<Vector2>& plan) {
    std::vector<Pass> passes;
    if (plan.size() < 2) return passes;
    geometry::PointArray points(static_cast<Eigen::Index>(plan.size()), 3);
    for (size_t i = 0; i < plan.size(); ++i) points.row(static_cast<Eigen::Index>(i)) << plan[i].x(), plan[i].y(), 0.0;
    std::vector<char> onBottom;
    dropAll(points, onBottom);
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

  // Points between a and b where the path bends more than a quarter of the tolerance off the chord, by
  // bisection (at most 8 levels): the tip dropped at each midpoint, raised to `floor` there if given.
  void bisect(const Vector3& a, const Vector3& b, int depth, Pass& out, SurfaceBallDrop::Result& state,
              bool& haveGuess, const std::function<double(const Vector2&)>& floor = {}) {
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

private:
  // The gap between positions `from` and `to` (the ball off the face in between) is a hole the tool
  // bridges: short enough, and nothing in it stands above the straight line between its rims.
  bool bridges(const geometry::PointArray& points, const std::vector<Vector2>& plan, size_t from, size_t to) const {
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

  size_t extend(const geometry::PointArray& points, const std::vector<Vector2>& plan, size_t end, int step) const {
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

  Pass refine(const geometry::PointArray& points, const std::vector<size_t>& indices) {
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

  // Douglas-Peucker: the fewest points within 3/4 of the tolerance of the refined polyline.
  Pass simplify(const Pass& pass) const {
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

// A one-parameter family of passes: parameter → plan polyline (coarse for the stepover, fine for cutting).
struct Family {
  std::function<std::vector<Vector2>(double parameter, double spacing)> plan;
  double begin = 0.0, end = 1.0;
};

// The share of the work a phase stands for: progress from `base` over `width`.
struct Phase {
  double base = 0.0, width = 1.0;
  double at(double done) const { return base + width * done; }
};

// The parameters of the passes from `begin` to `end`: each the farthest that keeps the cusp height.
// Progress: the first half of `phase`.
std::vector<double> passParameters(Context& context, const Family& family, bool skipFirst, Phase phase) {
  std::vector<double> parameters;
  double current = family.begin;
  if (!skipFirst) parameters.push_back(current);
  const double span = std::abs(family.end - family.begin), sense = family.end > family.begin ? 1.0 : -1.0;
  double lastStep = 1e-3 * span;
  while (std::abs(current - family.begin) < span - 1e-12) {
    const std::vector<Vector2> plan = family.plan(current, kStationStep);
    const std::vector<BallContact> here = context.gauge().contacts(plan);
    const double h = context.settings().cuspHeight, flat = context.flatStep();
    auto fits = [&](double candidate) {
      const std::vector<Vector2> candidatePlan = family.plan(candidate, kStationStep);
      const std::vector<BallContact> there = context.gauge().contacts(candidatePlan);
      for (size_t k = 0; k < here.size() && k < there.size(); ++k) {
        if (!there[k].inside) continue;
        // Where the current pass is off the face (or its cusp cannot be told), the next may not step by
        // more than the flat-face stepover in plan: the passes must not jump over a corner.
        const std::optional<double> cusp = context.gauge().cusp(here, k, candidatePlan, there, h);
        if (cusp ? *cusp > h : (candidatePlan[k] - plan[k]).norm() > flat) return false;
      }
      return true;
    };
    // Bracket the next pass from the last step (doubling while it fits), then bisect to 1 % of the step.
    double lo = current, step = std::max(lastStep, 1e-6 * span), hi = current;
    for (;;) {
      hi = sense > 0 ? std::min(current + sense * step, family.end) : std::max(current + sense * step, family.end);
      if (!fits(hi)) break;
      lo = hi;
      if (hi == family.end) break;
      step *= 2.0;
    }
    if (lo != family.end) {
      const double resolution = 0.01 * std::abs(hi - current);
      while (std::abs(hi - lo) > resolution) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
      }
    }
    lastStep = std::max(std::abs(lo - current), 1e-6 * span);
    if (std::abs(lo - current) < 1e-9 * span) lo = current + sense * 1e-3 * span;  // always move on
    current = sense > 0 ? std::min(lo, family.end) : std::max(lo, family.end);
    parameters.push_back(current);
    context.report(phase.at(0.5 * std::abs(current - family.begin) / span));
  }
  return parameters;
}

// The passes of a family cut along the parameters; progress: the second half of `phase`.
std::vector<std::vector<Pass>> cutPasses(Context& context, const Family& family, const std::vector<double>& parameters,
                                         Phase phase) {
  std::vector<std::vector<Pass>> lines;
  for (size_t k = 0; k < parameters.size(); ++k) {
    std::vector<Pass> cut = context.cut(family.plan(parameters[k], context.settings().sampling));
    if (!cut.empty()) lines.push_back(std::move(cut));
    context.report(phase.at(0.5 + 0.5 * double(k + 1) / double(parameters.size())));
  }
  return lines;
}

double meanHeight(const std::vector<std::vector<Pass>>& lines) {
  double sum = 0.0;
  long n = 0;
  for (const auto& line : lines)
    for (const Pass& p : line)
      for (const Vector3& x : p) {
        sum += x.z();
        ++n;
      }
  return n ? sum / n : 0.0;
}

// A G1 link from the end of a pass to the start of the next that follows the surface (dropped, so it
// cannot gouge), or none when it would climb a wall (lifted more than the tool radius above the straight
// line): then the tool retracts instead.
std::vector<Vector3> surfaceLink(Context& context, const Vector3& from, const Vector3& to) {
  const FinishingSettings& s = context.settings();
  const int steps = std::max(2, int(std::ceil((to - from).head<2>().norm() / s.sampling)));
  const double span = (to - from).head<2>().norm();
  auto line = [&](const Vector2& p) {
    return span > 0.0 ? from.z() + (to.z() - from.z()) * (p - from.head<2>()).norm() / span : from.z();
  };
  std::vector<Vector3> samples{from};
  for (int i = 1; i < steps; ++i) {
    Vector3 p = from + (to - from) * double(i) / steps;
    const double straight = p.z();
    p.z() = std::max(p.z(), context.tipAt(p.x(), p.y()));
    if (p.z() - straight > s.toolRadius) return {};
    samples.push_back(p);
  }
  samples.push_back(to);
  // Refined between the samples as passes are: a link over an edge bends, and its chords must not cut.
  std::vector<Vector3> link;
  SurfaceBallDrop::Result state;
  bool haveGuess = false;
  for (size_t k = 1; k < samples.size(); ++k) {
    context.bisect(samples[k - 1], samples[k], 0, link, state, haveGuess, line);
    if (k + 1 < samples.size()) link.push_back(samples[k]);
  }
  return link;
}

// A feed move to `p`, unless the tool is there already (a pass that starts where the previous one ended:
// a zero-length G1 is noise that posts round away).
void addFeed(Toolpath& path, const Vector3& p) {
  if (!path.moves.empty() && (path.moves.back().point - p).norm() < 1e-4) return;
  path.moves.push_back({p, false});
}

// Links passes into moves: zigzag neighbours by a surface-following G1 when close, else retract.
Toolpath assemble(Context& context, std::vector<std::vector<Pass>> lines) {
  const FinishingSettings& s = context.settings();
  Toolpath path;
  path.safeHeight = context.safeHeight();
  // Zigzag: every other line (a plane, or a morphed pass) runs backwards, its pieces in reverse order too.
  std::vector<Pass> passes;
  for (size_t k = 0; k < lines.size(); ++k) {
    if (s.zigzag && k % 2 == 1) {
      std::reverse(lines[k].begin(), lines[k].end());
      for (Pass& piece : lines[k]) std::reverse(piece.begin(), piece.end());
    }
    passes.insert(passes.end(), lines[k].begin(), lines[k].end());
  }
  const double linkLimit = 10.0 * s.toolRadius;
  bool inside = false;  // the tool is down at the end of the previous pass
  for (const Pass& pass : passes) {
    if (pass.size() < 2) continue;
    ++path.passes;
    double length = 0.0;
    for (size_t k = 1; k < pass.size(); ++k) length += (pass[k] - pass[k - 1]).norm();
    path.passLengths.push_back(length);
    const Vector3& start = pass.front();
    std::vector<Vector3> link;
    if (inside && s.zigzag && (start - path.moves.back().point).norm() <= linkLimit)
      link = surfaceLink(context, path.moves.back().point, start);
    if (!link.empty()) {
      for (const Vector3& p : link) addFeed(path, p);
    } else {
      if (inside) path.moves.push_back({Vector3(path.moves.back().point.x(), path.moves.back().point.y(), path.safeHeight), true});
      path.moves.push_back({Vector3(start.x(), start.y(), path.safeHeight), true});
      path.moves.push_back({Vector3(start.x(), start.y(), start.z() + 1.0), true});
    }
    for (const Vector3& p : pass) addFeed(path, p);
    inside = true;
  }
  if (inside) path.moves.push_back({Vector3(path.moves.back().point.x(), path.moves.back().point.y(), path.safeHeight), true});
  return path;
}

// Groups (areas) of lines (passes, each in pieces) in sweeping order: upward starts on the lower side.
void orderForSweep(std::vector<std::vector<std::vector<Pass>>>& groups, Sweep sweep) {
  groups.erase(std::remove_if(groups.begin(), groups.end(), [](const auto& g) { return g.empty(); }), groups.end());
  if (groups.empty()) return;
  // Several areas: compare the first and last areas; one area: its first and last passes.
  const bool single = groups.size() == 1;
  const double firstHeight = single ? meanHeight({groups.front().front()}) : meanHeight(groups.front());
  const double lastHeight = single ? meanHeight({groups.front().back()}) : meanHeight(groups.back());
  const bool climbing = lastHeight >= firstHeight;
  if (climbing != (sweep == Sweep::Upward)) {
    std::reverse(groups.begin(), groups.end());
    for (auto& g : groups) std::reverse(g.begin(), g.end());
  }

}

// The lines (each a list of pass pieces) of all groups, in order.
std::vector<std::vector<Pass>> lines(const std::vector<std::vector<std::vector<Pass>>>& groups) {
  std::vector<std::vector<Pass>> all;
  for (const auto& g : groups) all.insert(all.end(), g.begin(), g.end());
  return all;
}

}  // namespace

namespace {
// The passes of all groups linked into moves; refuses a result with no pass at all (nothing to cut).
Toolpath finish(Context& context, std::vector<std::vector<std::vector<Pass>>> groups, int bottomFace,
                const std::string& why) {
  orderForSweep(groups, context.settings().sweep);
  if (groups.empty())
    throw InputError("no pass of the " + mm(2.0 * context.settings().toolRadius) + " ball rests on " +
                     faceName(bottomFace) + ": " + why);
  Toolpath path = assemble(context, lines(groups));
  path.droppedPoints = context.dropped;
  path.warnings.insert(path.warnings.begin(), context.warnings.begin(), context.warnings.end());
  context.report(1.0);
  return path;
}
}  // namespace

Toolpath parallelPlaneFinishing(const TopoDS_Shape& part, int bottomFace, double angleDeg,
                                const FinishingSettings& settings) {
  if (!std::isfinite(angleDeg)) throw InputError("the angle of the planes must be a number of degrees");
  Context context(part, bottomFace, settings);
  const double a = angleDeg * M_PI / 180.0;
  const Vector2 along(std::cos(a), std::sin(a)), across(-std::sin(a), std::cos(a));
  const Vector2 lo = context.faceMin(), hi = context.faceMax();
  double a0 = kInfinity, a1 = -kInfinity, q0 = kInfinity, q1 = -kInfinity;
  for (const Vector2& corner : {lo, hi, Vector2(lo.x(), hi.y()), Vector2(hi.x(), lo.y())}) {
    a0 = std::min(a0, corner.dot(along));
    a1 = std::max(a1, corner.dot(along));
    q0 = std::min(q0, corner.dot(across));
    q1 = std::max(q1, corner.dot(across));
  }
  const double margin = settings.toolRadius + 1.0;
  context.checkWork(q1 - q0, a1 - a0 + 2.0 * margin);
  Family family;
  family.begin = q0 + 1e-3;
  family.end = q1 - 1e-3;
  family.plan = [=](double q, double spacing) {
    std::vector<Vector2> plan;
    for (double t = a0 - margin; t <= a1 + margin + 1e-9; t += spacing) plan.push_back(t * along + q * across);
    return plan;
  };
  const std::vector<double> parameters = passParameters(context, family, false, {});
  return finish(context, {cutPasses(context, family, parameters, {})}, bottomFace,
                "the walls around it hold the tool up everywhere (a ball finishes a floor only where it fits): use "
                "a smaller ball");
}

namespace {
// Points of the guides in the planes of one spacing: every pass is a blend of the same two point lists.
class GuidePoints {
public:
  GuidePoints(const geometry::PlaneCutter& first, const geometry::PlaneCutter& second, double s0,
              double s1)
      : first_(first), second_(second), s0_(s0), s1_(s1) {}

  const std::pair<geometry::PointArray, geometry::PointArray>& at(double spacing) {
    auto found = cache_.find(spacing);
    if (found != cache_.end()) return found->second;
    std::vector<double> stations;
    for (double s = s0_; s < s1_; s += spacing) stations.push_back(s);
    stations.push_back(s1_);
    return cache_.emplace(spacing, std::make_pair(first_.cut(stations).points, second_.cut(stations).points))
        .first->second;
  }

private:
  const geometry::PlaneCutter &first_, &second_;
  double s0_, s1_;
  std::map<double, std::pair<geometry::PointArray, geometry::PointArray>> cache_;
};
}  // namespace

Toolpath guideCurveFinishing(const TopoDS_Shape& part, int bottomFace, const std::vector<GuideArea>& areas,
                             const Eigen::Vector3d& directionIn, const FinishingSettings& settings) {
  if (areas.empty()) throw InputError("no area to machine: give at least one pair of guide curves");
  if (!directionIn.allFinite() || directionIn.head<2>().norm() < 1e-9)
    throw InputError("the machining direction must be a horizontal vector, e.g. (1, 0, 0)");
  Context context(part, bottomFace, settings);
  const Vector3 direction = Vector3(directionIn.x(), directionIn.y(), 0.0).normalized();
  std::vector<std::vector<std::vector<Pass>>> groups;
  const double extension = (settings.extension >= 0 ? settings.extension : settings.toolRadius) + 1.0;
  for (size_t index = 0; index < areas.size(); ++index) {
    const GuideArea& area = areas[index];
    const std::string name = "area " + std::to_string(index + 1);
    if (area.first.IsNull() || area.second.IsNull()) throw InputError(name + " lacks a guide");
    const geometry::PlaneCutter first(area.first, direction), second(area.second, direction);
    const double s0 = std::max(first.extent().first, second.extent().first);
    const double s1 = std::min(first.extent().second, second.extent().second);
    if (s1 - s0 < settings.sampling)
      throw InputError("the guides of " + name + " do not overlap along the machining direction: pick guides "
                       "on either side of the area");
    GuidePoints guides(first, second, s0, s1);
    const auto& [a, b] = guides.at(std::max(settings.sampling, (s1 - s0) / 200.0));
    const double width = (b - a).leftCols(2).rowwise().norm().maxCoeff();
    if (width < 1e-3)
      throw InputError("the guides of " + name + " coincide (at most " + mm(width) + " apart): pick two different "
                       "curves on either side of the area");
    context.checkWork(width, s1 - s0 + 2.0 * extension);
    Family family;
    family.plan = [&guides, extension](double lambda, double spacing) {
      const auto& [a, b] = guides.at(spacing);
      std::vector<Vector2> plan;
      for (Eigen::Index k = 0; k < a.rows(); ++k) {
        const Eigen::RowVector3d p = a.row(k) + lambda * (b.row(k) - a.row(k));
        plan.emplace_back(p.x(), p.y());
      }
      // Straight on past both ends, so that the pass can leave an open boundary.
      if (plan.size() >= 2) {
        const Vector2 head = (plan[0] - plan[1]).normalized(), tail = (plan.back() - plan[plan.size() - 2]).normalized();
        const Vector2 start = plan.front(), end = plan.back();
        std::vector<Vector2> before, after;
        for (double e = spacing; e <= extension + 1e-9; e += spacing) {
          before.push_back(start + e * head);
          after.push_back(end + e * tail);
        }
        plan.insert(plan.begin(), before.rbegin(), before.rend());
        plan.insert(plan.end(), after.begin(), after.end());
      }
      return plan;
    };
    const Phase phase{double(index) / areas.size(), 1.0 / areas.size()};
    const std::vector<double> parameters = passParameters(context, family, index > 0, phase);
    groups.push_back(cutPasses(context, family, parameters, phase));
  }
  return finish(context, std::move(groups), bottomFace,
                "check that the guides lie on the face, and that the ball fits between its walls");
}

}  // namespace hsm::toolpath
