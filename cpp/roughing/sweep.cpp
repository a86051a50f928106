// Slicings swept by contour-parallel passes (sweep.hpp): each level laid flat (planes as they are, cylinders
// unrolled), its region, shadow and domain in Clipper's integer plane, its offsets, then entries, loops and
// links as tool moves.
#include "roughing/sweep.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace hsm::roughing {

namespace {
constexpr int kMaxRings = 10000;
constexpr double kOverhang = 0.1;  // of the diameter: the outer pass goes this far past the slice's outline
constexpr double kFloorSlack = 0.005;  // mm

cl::Paths offset(const cl::Paths& paths, double mm, double tolerance) {
  cl::ClipperOffset offsetter(2.0, std::max(1.0, tolerance * kScale));
  offsetter.AddPaths(paths, cl::jtRound, cl::etClosedPolygon);
  cl::Paths result;
  offsetter.Execute(result, mm * kScale);
  return result;
}

cl::Paths boolean(cl::ClipType type, const cl::Paths& a, const cl::Paths& b) {
  cl::Clipper clipper;
  clipper.AddPaths(a, cl::ptSubject, true);
  clipper.AddPaths(b, cl::ptClip, true);
  cl::Paths result;
  clipper.Execute(type, result, cl::pftNonZero, cl::pftNonZero);
  return result;
}

// A rectangle of the plane, in Clipper units: what is outside it does not matter for a level.
struct Window {
  double x0 = -std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  bool misses(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) const {
    return std::max({a.X, b.X, c.X}) < x0 || std::min({a.X, b.X, c.X}) > x1 || std::max({a.Y, b.Y, c.Y}) < y0 ||
           std::min({a.Y, b.Y, c.Y}) > y1;
  }
};

Window windowAround(const cl::Paths& paths, double margin) {
  Window w;
  if (paths.empty()) return w;
  const cl::IntRect r = [&] {
    cl::Clipper c;
    c.AddPaths(paths, cl::ptSubject, true);
    return c.GetBounds();
  }();
  w.x0 = double(r.left) - margin * kScale, w.x1 = double(r.right) + margin * kScale;
  w.y0 = double(r.top) - margin * kScale, w.y1 = double(r.bottom) + margin * kScale;
  return w;
}

// The straight edge a–b laid flat, from a (included) towards b (excluded): points added at midpoints while the
// projection bows it.
void addFlatEdge(const Projection& projection, const Eigen::Vector3d& a, const Eigen::Vector3d& b, int depth,
                 cl::Path& path) {
  if (depth < 6 && projection.bends(a, b)) {
    const Eigen::Vector3d m = 0.5 * (a + b);
    addFlatEdge(projection, a, m, depth + 1, path);
    addFlatEdge(projection, m, b, depth + 1, path);
    return;
  }
  path.push_back(projection.plane(a));
}

// The triangle p laid flat, cut to its part at or above `fromHeight`, added to `pieces`: the polygon of its
// edges' images (bowed where the projection bends straight edges).
void addProjected(const Projection& projection, const Eigen::Vector3d (&p)[3], double fromHeight,
                  const Window& window, cl::Paths& pieces) {
  if (projection.skip(p) || window.misses(projection.plane(p[0]), projection.plane(p[1]), projection.plane(p[2])))
    return;
  const double h[3] = {projection.height(p[0]), projection.height(p[1]), projection.height(p[2])};
  if (std::max({h[0], h[1], h[2]}) < fromHeight) return;
  std::vector<Eigen::Vector3d> kept;  // the triangle cut by the half-space height ≥ fromHeight
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (h[i] >= fromHeight) kept.push_back(p[i]);
    if ((h[i] >= fromHeight) != (h[j] >= fromHeight))
      kept.push_back(p[i] + (p[j] - p[i]) * ((fromHeight - h[i]) / (h[j] - h[i])));
  }
  cl::Path path;
  for (size_t i = 0; i < kept.size(); ++i) addFlatEdge(projection, kept[i], kept[(i + 1) % kept.size()], 0, path);
  if (path.size() < 3) return;
  if (!cl::Orientation(path)) cl::ReversePath(path);  // all counter-clockwise: their union is non-zero
  if (cl::Area(path) > 0.0) pieces.push_back(std::move(path));
}

// The mesh's triangles laid flat, each cut to its part at or above `fromHeight` (−∞: whole), leaving out those
// outside `window`, gathered in bins by `binOf(triangle)`: what stands over the surface, seen along the tool
// axis. The mesh is of closed solids, its triangles facing out: on planes only those facing the spindle are
// needed (a ray along the tool axis from any point of the solid leaves it through one of them), half the
// union's work. (Unrolled cylinders keep every triangle: culled there, S2's levels lost part of their region,
// 121 against 150 mm of cutting on an impeller channel, for a reason not found yet.)
template <class BinOf>
std::map<int, cl::Paths> projectedPieces(const geometry::TriangleMesh& mesh, const Projection& projection,
                                         double fromHeight, const Window& window, BinOf&& binOf) {
  std::map<int, cl::Paths> bins;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    if (std::max({projection.height(p[0]), projection.height(p[1]), projection.height(p[2])}) < fromHeight) continue;
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (projection.cullsBackFaces() && normal.dot(projection.axisAt((p[0] + p[1] + p[2]) / 3.0)) <= 0.0) continue;
    addProjected(projection, p, fromHeight, window, bins[binOf(p)]);
  }
  return bins;
}

cl::Paths united(const cl::Paths& pieces) {
  cl::Clipper clipper;
  clipper.AddPaths(pieces, cl::ptSubject, true);
  cl::Paths result;
  clipper.Execute(cl::ctUnion, result, cl::pftNonZero, cl::pftNonZero);
  return result;
}

// The union of the mesh's triangles laid flat (projectedPieces).
cl::Paths projectedUnion(const geometry::TriangleMesh& mesh, const Projection& projection, double fromHeight,
                         const Window& window = {}) {
  return united(projectedPieces(mesh, projection, fromHeight, window, [](const Eigen::Vector3d(&)[3]) { return 0; })[0]);
}

// Clipper paths with x scaled by `factor`.
cl::Paths scaledX(cl::Paths paths, double factor) {
  for (cl::Path& path : paths)
    for (cl::IntPoint& q : path) q.X = static_cast<cl::cInt>(std::llround(double(q.X) * factor));
  return paths;
}

// Where the tool's centre may not go (as paths to fill non-zero): the part's triangles at or above `fromHeight` laid flat, each grown by
// `clearance` true mm, that is by the clearance over the plane's scale along x and along y where the triangle
// is (an ellipse's growth: bins of scales 5 % apart, each bin's union stretched along x to its y scale, grown
// by the clearance over the bin's least y scale, and stretched back).
cl::Paths keepOutOf(const geometry::TriangleMesh& mesh, const Projection& projection, double fromHeight,
                    const Window& window, double clearance, double tolerance, const cl::Paths& within) {
  // Only what falls on `within` matters (the tool's centre is kept there): each bin's growth is cut to its
  // bounding rectangle before the difference unites them all. Where the centre goes nowhere (a level the
  // tool fits nowhere in), nothing is kept out: the window of no path is unbounded, not a rectangle.
  if (within.empty()) return {};
  const Window box = windowAround(within, 1.0);
  const cl::Paths rectangle = {{{cl::cInt(box.x0), cl::cInt(box.y0)}, {cl::cInt(box.x1), cl::cInt(box.y0)},
                                {cl::cInt(box.x1), cl::cInt(box.y1)}, {cl::cInt(box.x0), cl::cInt(box.y1)}}};
  const double ratio = 1.05;
  auto level = [&](double scale) {
    return static_cast<int>(std::floor(std::log(std::clamp(scale, 1e-3, 1e3)) / std::log(ratio)));
  };
  const auto bins = projectedPieces(mesh, projection, fromHeight, window, [&](const Eigen::Vector3d(&p)[3]) {
    const Eigen::Vector2d s = projection.scalesAt(p[0]).cwiseMin(projection.scalesAt(p[1])).cwiseMin(projection.scalesAt(p[2]));
    return level(s.x()) * 4096 + level(s.y());  // both levels within ±142: one key
  });
  cl::Paths grown;
  for (const auto& [key, pieces] : bins) {
    const int ix = static_cast<int>(std::lround(double(key) / 4096.0)), iy = key - ix * 4096;
    const double sx = std::pow(ratio, ix), sy = std::pow(ratio, iy);
    // The least scales of the bin (its lower edges): x stretched by sx/sy makes the plane's metric sy both ways.
    const cl::Paths part = boolean(cl::ctIntersection,
                                   scaledX(offset(scaledX(united(pieces), sx / sy), clearance / sy, tolerance), sy / sx),
                                   rectangle);
    grown.insert(grown.end(), part.begin(), part.end());
  }
  // Not united: each bin's paths wind once round what they cover (holes cancel their own outline), so their
  // sum is non-zero exactly where some bin covers; the difference that uses them unites them on the way.
  return grown;
}

// Points added along each edge longer than `longest` (mm; ∞: none): straight in the flat passes, the moves
// between them stay within the tolerance of the surface.
void densify(cl::Paths& paths, double longest) {
  if (!std::isfinite(longest)) return;
  for (cl::Path& path : paths) {
    cl::Path dense;
    for (size_t i = 0; i < path.size(); ++i) {
      const cl::IntPoint& a = path[i];
      const cl::IntPoint& b = path[(i + 1) % path.size()];
      dense.push_back(a);
      const double length = std::hypot(double(b.X - a.X), double(b.Y - a.Y)) / kScale;
      const int pieces = static_cast<int>(std::ceil(length / longest));
      for (int k = 1; k < pieces; ++k)
        dense.push_back({static_cast<cl::cInt>(a.X + (b.X - a.X) * double(k) / pieces),
                         static_cast<cl::cInt>(a.Y + (b.Y - a.Y) * double(k) / pieces)});
    }
    path = std::move(dense);
  }
}

double pathLength(const cl::Path& path) {
  double length = 0.0;
  for (size_t i = 1; i < path.size(); ++i)
    length += std::hypot(double(path[i].X - path[i - 1].X), double(path[i].Y - path[i - 1].Y));
  return length / kScale;
}

// Whether the straight segment a–b lies in the domain (within the tolerance).
bool segmentInside(const cl::IntPoint& a, const cl::IntPoint& b, const cl::Paths& domain, double tolerance) {
  cl::Clipper clipper;
  clipper.AddPath(cl::Path{a, b}, cl::ptSubject, false);
  clipper.AddPaths(domain, cl::ptClip, true);
  cl::PolyTree tree;
  clipper.Execute(cl::ctIntersection, tree, cl::pftNonZero, cl::pftNonZero);
  cl::Paths open;
  cl::OpenPathsFromPolyTree(tree, open);
  double inside = 0.0;
  for (const cl::Path& p : open) inside += pathLength(p);
  return inside >= pathLength(cl::Path{a, b}) - tolerance;
}

// Distance (mm) from q to the nearest point of the paths' boundaries, and whether q is inside them.
double distanceToBoundary(const cl::IntPoint& q, const cl::Paths& paths) {
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d p(double(q.X), double(q.Y));
  for (const cl::Path& path : paths)
    for (size_t i = 0; i < path.size(); ++i) {
      const Eigen::Vector2d a(double(path[i].X), double(path[i].Y));
      const cl::IntPoint& nb = path[(i + 1) % path.size()];
      const Eigen::Vector2d b(double(nb.X), double(nb.Y));
      const Eigen::Vector2d d = b - a;
      const double t = d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (a + t * d - p).norm());
    }
  return best / kScale;
}

bool insidePaths(const cl::IntPoint& q, const cl::Paths& paths) {
  int winding = 0;
  for (const cl::Path& path : paths) {
    const int in = cl::PointInPolygon(q, path);
    if (in != 0) winding += cl::Orientation(path) ? 1 : -1;
  }
  return winding > 0;
}

struct Level {
  int subVolume = 0;
  double tip = 0.0, top = 0.0;  // heights along the axis: the tip's plane and the slice's near side
  cl::Paths region, domain;
  std::vector<cl::Paths> rings;
};

class Sweeper {
public:
  Sweeper(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part, const TopoDS_Shape& stock,
          const SweepSettings& settings)
      : partition_(partition), settings_(settings), projection_(projectionOf(partition, solid)),
        partMesh_(geometry::meshFacesAfresh(part, settings.meshDeflection)) {
    const geometry::TriangleMesh stockMesh = geometry::meshFaces(stock, std::max(0.05, settings.meshDeflection));
    double high = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : stockMesh.vertices) high = std::max(high, projection_->height(p));
    safeHeight_ = high + settings.clearance;
  }

  SweepResult run() {
    const int count = static_cast<int>(partition_.subVolumes.size());
    // From the crossable face inwards: S5's slices are numbered from the hub, the tool comes from the skin.
    const bool fromLast = partition_.strategy == Strategy::HubOffsets;
    for (int k = 0; k < count; ++k) {
      if (settings_.progress && !settings_.progress(double(k) / count)) throw Cancelled("sweep");
      const int i = fromLast ? count - 1 - k : k;
      Level level = makeLevel(i);
      if (level.rings.empty()) {
        result_.warnings.push_back("slice " + std::to_string(partition_.subVolumes[i].slice) +
                                   ": the tool fits nowhere in it (narrower than the tool, or under the part)");
        continue;
      }
      sweepLevel(level);
    }
    if (!result_.moves.empty()) retract();
    if (settings_.progress) settings_.progress(1.0);
    return std::move(result_);
  }

private:
  // The height of the slice's slicing surface (sweep.hpp: the near side, or S5's far side).
  double surfaceHeight(const SubVolume& sub) const {
    if (sub.surface.kind == SurfaceKind::Cylinder) return sub.surface.radius;
    if (sub.surface.kind == SurfaceKind::Plane) return projection_->height(sub.surface.origin);
    if (sub.axisPoints.empty()) throw ComputationError("slice " + std::to_string(sub.slice) + " has no point on its surface");
    return projection_->height(sub.axisPoints.front());
  }

  Level makeLevel(int index) {
    const SubVolume& sub = partition_.subVolumes[index];
    Level level;
    level.subVolume = index;
    const geometry::TriangleMesh mesh = geometry::meshFacesAfresh(sub.shape, settings_.meshDeflection);
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const Eigen::Vector3d& p : mesh.vertices) {
      const double h = projection_->height(p);
      low = std::min(low, h), high = std::max(high, h);
    }
    const double radius = settings_.cutter.radius();
    const double surface = surfaceHeight(sub);
    if (partition_.strategy == Strategy::HubOffsets) {
      // The slicing surface is the slice's far side; the reference (the hub, a floor) is part of the part: the
      // tip stays the allowance above it, and the lift of the tool's rim over a concave hub.
      projection_->setLevel(surface, mesh);
      const double lift = rimLift();
      level.top = std::min(surface + partition_.step, high);
      level.tip = std::max(surface, surface - sub.surface.offset + settings_.allowance + lift + settings_.meshDeflection);
      level.top = std::max(level.top, level.tip + settings_.tolerance);
    } else {
      level.top = surface;
      level.tip = std::max(level.top - partition_.step, low);
      projection_->setLevel(level.tip, mesh);
      raiseOverFloor(level);
    }
    projection_->setLevel(level.tip, mesh);
    const double lift = rimLift();
    level.region = projectedUnion(mesh, *projection_, -std::numeric_limits<double>::infinity());
    // Only the part near the region matters: within the tool's radius, the allowance and a margin of it.
    const double margin = (radius + settings_.allowance + settings_.meshDeflection + 1.0) / projection_->smallestScale();
    const double scale = projection_->largestScale();
    const cl::Paths inner = offset(level.region, -(radius - kOverhang * settings_.cutter.diameter) / scale, settings_.tolerance);
    // Grown by the mesh's deflection and the offsets' arc tolerance too (their chords cut inside the arcs).
    // The part from the allowance under the tip up, less 5 µm: a floor the tip was raised onto lies exactly the
    // allowance under it, and rounding (a shape read back from BREP text, or not) must not decide whether it
    // shadows the whole level (half the 0.01 mm the clearance check grants).
    const cl::Paths keepOut = keepOutOf(partMesh_, *projection_, level.tip - settings_.allowance - lift + kFloorSlack,
                                        windowAround(level.region, 1.5 * margin),
                                        radius + settings_.allowance + settings_.meshDeflection + settings_.tolerance,
                                        settings_.tolerance, inner);
    level.domain = boolean(cl::ctDifference, inner, keepOut);
    // Passes never farther apart than the engagement asked, where the plane is most stretched.
    const double step = settings_.radialEngagement * settings_.cutter.diameter / scale;
    for (int k = 0; k < kMaxRings; ++k) {
      cl::Paths ring = k == 0 ? level.domain : offset(level.domain, -k * step, settings_.tolerance);
      cl::CleanPolygons(ring, settings_.tolerance * kScale);
      if (ring.empty()) break;
      densify(ring, projection_->maxSegment(level.tip, settings_.tolerance));
      level.rings.push_back(std::move(ring));
    }
    return level;
  }

  // How much nearer the surface the rim of the tool's disk (grown by the allowance) is than its centre.
  double rimLift() const {
    const double r = settings_.cutter.radius() + settings_.allowance;
    return 0.5 * r * r * projection_->concavity();
  }

  // A face of the part parallel to the plane within the allowance under the tip (a floor): the tip stays the
  // allowance above it, or the whole floor would be out of reach.
  void raiseOverFloor(Level& level) const {
    double floor = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3i& t : partMesh_.triangles) {
      const Eigen::Vector3d& p0 = partMesh_.vertices[t[0]];
      const Eigen::Vector3d n = (partMesh_.vertices[t[1]] - p0).cross(partMesh_.vertices[t[2]] - p0);
      if (!(n.norm() > 0.0) || n.normalized().dot(projection_->axisAt(p0)) < 1.0 - 1e-6) continue;
      const double h = projection_->height(p0);
      if (h > level.tip - settings_.allowance - 1e-9 && h < level.tip + settings_.allowance) floor = std::max(floor, h);
    }
    const double raised = floor + settings_.allowance + rimLift();
    if (std::isfinite(floor) && raised < level.top) level.tip = raised;
  }

  void add(MoveKind kind, const Eigen::Vector3d& tip, int subVolume) {
    if (!result_.moves.empty()) {
      const double length = (tip - result_.moves.back().tip).norm();
      if (length < 1e-9) return;
      switch (kind) {
        case MoveKind::Cut: result_.cuttingLength += length; break;
        case MoveKind::Ramp: case MoveKind::Plunge: result_.rampLength += length; break;
        case MoveKind::Link: result_.linkLength += length; break;
        case MoveKind::Rapid: result_.rapidLength += length; break;
      }
    }
    result_.moves.push_back({kind, tip, projection_->axisAt(tip), subVolume});
  }

  void retract() {
    const Eigen::Vector3d at = result_.moves.back().tip;
    add(MoveKind::Rapid, projection_->point(projection_->plane(at), safeHeight_), -1);
    ++result_.retracts;
  }

  // At the safe height, from where the tool is to above `to`, in steps that keep it there (cylinders: arcs).
  void travel(const cl::IntPoint& to) {
    const cl::IntPoint from = projection_->plane(result_.moves.back().tip);
    const double length = std::hypot(double(to.X - from.X), double(to.Y - from.Y)) / kScale;
    const double longest = projection_->maxSegment(safeHeight_, std::max(1.0, settings_.clearance / 2.0));
    const int pieces = std::isfinite(longest) ? std::max(1, static_cast<int>(std::ceil(length / longest))) : 1;
    for (int k = 1; k <= pieces; ++k)
      add(MoveKind::Rapid, projection_->point({static_cast<cl::cInt>(from.X + (to.X - from.X) * double(k) / pieces),
                                               static_cast<cl::cInt>(from.Y + (to.Y - from.Y) * double(k) / pieces)},
                                              safeHeight_), -1);
  }

  // Where an entry reaches the level: on the loop's segment from point `index` to the next, at `point`.
  struct Arrival {
    size_t index;
    cl::IntPoint point;
  };

  // Down to the loop's start: a plunge where the tool's disk is clear of the slice's material, else a ramp
  // along the loop from the slice's near side. The full loop is then cut from where the tool reaches the level.
  Arrival enter(const Level& level, const cl::Path& loop, size_t start) {
    const Eigen::Vector3d first = projection_->point(loop[start], level.top + 1.0);
    if (result_.moves.empty()) add(MoveKind::Rapid, projection_->point(loop[start], safeHeight_), -1);
    else if (projection_->height(result_.moves.back().tip) > safeHeight_ - 1e-9) travel(loop[start]);
    add(MoveKind::Rapid, first, level.subVolume);
    const bool clear = !insidePaths(loop[start], level.region) &&
                       distanceToBoundary(loop[start], level.region) >= settings_.cutter.radius();
    if (clear) {
      add(MoveKind::Plunge, projection_->point(loop[start], level.tip), level.subVolume);
      ++result_.plunges;
      return {start, loop[start]};
    }
    // Ramp: the height falls linearly with the path along the loop, round it as often as needed.
    const double drop = level.top + 1.0 - level.tip;
    const double rampLength = drop / std::tan(settings_.rampAngleDeg * M_PI / 180.0);
    double travelled = 0.0;
    size_t i = start;
    while (travelled < rampLength - 1e-9) {
      const size_t j = (i + 1) % loop.size();
      const double segment = std::hypot(double(loop[j].X - loop[i].X), double(loop[j].Y - loop[i].Y)) / kScale;
      if (segment <= 0.0) {
        i = j;
        continue;
      }
      const double take = std::min(segment, rampLength - travelled);
      travelled += take;
      const double f = take / segment;
      const cl::IntPoint q{static_cast<cl::cInt>(loop[i].X + f * (loop[j].X - loop[i].X)),
                           static_cast<cl::cInt>(loop[i].Y + f * (loop[j].Y - loop[i].Y))};
      add(MoveKind::Ramp, projection_->point(q, level.top + 1.0 - drop * travelled / rampLength), level.subVolume);
      if (take < segment) {  // the ramp ends inside the segment
        ++result_.ramps;
        return {i, q};
      }
      i = j;
    }
    ++result_.ramps;
    return {i, loop[i]};
  }

  // The whole loop at the level from `from` (on the segment after point `from.index`) round to it again.
  void cutLoop(const Level& level, const cl::Path& loop, const Arrival& from, int ring) {
    Pass pass;
    pass.subVolume = level.subVolume;
    pass.ring = ring;
    for (size_t k = 1; k <= loop.size(); ++k) {
      const Eigen::Vector3d p = projection_->point(loop[(from.index + k) % loop.size()], level.tip);
      add(MoveKind::Cut, p, level.subVolume);
      pass.points.push_back(p);
    }
    add(MoveKind::Cut, projection_->point(from.point, level.tip), level.subVolume);
    result_.passes.push_back(std::move(pass));
  }

  void sweepLevel(const Level& level) {
    bool entered = false;
    for (size_t k = 0; k < level.rings.size(); ++k) {
      std::vector<bool> done(level.rings[k].size(), false);
      for (size_t n = 0; n < level.rings[k].size(); ++n) {
        // The nearest loop to where the tool is, and its nearest point.
        const cl::IntPoint here = entered ? projection_->plane(result_.moves.back().tip) : level.rings[k][0][0];
        size_t best = 0, bestPoint = 0;
        double bestDistance = std::numeric_limits<double>::infinity();
        for (size_t l = 0; l < level.rings[k].size(); ++l) {
          if (done[l]) continue;
          const cl::Path& loop = level.rings[k][l];
          for (size_t p = 0; p < loop.size(); ++p) {
            const double d = std::hypot(double(loop[p].X - here.X), double(loop[p].Y - here.Y));
            if (d < bestDistance) bestDistance = d, best = l, bestPoint = p;
          }
        }
        done[best] = true;
        const cl::Path& loop = level.rings[k][best];
        if (loop.size() < 3) continue;
        Arrival from{bestPoint, loop[bestPoint]};
        if (entered && segmentInside(here, loop[bestPoint], level.domain, settings_.tolerance)) {
          link(here, loop[bestPoint], level);
        } else {
          if (entered) retract();
          from = enter(level, loop, bestPoint);
        }
        entered = true;
        cutLoop(level, loop, from, static_cast<int>(k));
      }
    }
    retract();
  }

  // A straight move at the level in the flat passes (points added where the surface bends).
  void link(const cl::IntPoint& from, const cl::IntPoint& to, const Level& level) {
    const double length = std::hypot(double(to.X - from.X), double(to.Y - from.Y)) / kScale;
    const double longest = projection_->maxSegment(level.tip, settings_.tolerance);
    const int pieces = std::isfinite(longest) ? std::max(1, static_cast<int>(std::ceil(length / longest))) : 1;
    for (int k = 1; k <= pieces; ++k)
      add(MoveKind::Link, projection_->point({static_cast<cl::cInt>(from.X + (to.X - from.X) * double(k) / pieces),
                                              static_cast<cl::cInt>(from.Y + (to.Y - from.Y) * double(k) / pieces)},
                                             level.tip), level.subVolume);
  }

  const Partition& partition_;
  const SweepSettings& settings_;
  std::unique_ptr<Projection> projection_;
  geometry::TriangleMesh partMesh_;
  double safeHeight_ = 0.0;
  SweepResult result_;
};

void checkSettings(const SweepSettings& s) {
  checkCutter(s.cutter);
  auto check = [](double value, double low, double high, const std::string& what, const std::string& fix) {
    if (!(value >= low && value <= high))
      throw InputError(what + " = " + number(value) + " is outside [" + number(low) + ", " + number(high) + "]: " + fix);
  };
  // At least 1 % of the diameter: below it the rings of a level would run into the thousands.
  if (!(s.radialEngagement >= 0.01 && s.radialEngagement <= 1.0))
    throw InputError("radial engagement = " + number(s.radialEngagement) +
                     " must be in [0.01, 1] (a share of the tool's diameter; the paper uses 0.7)");
  check(s.allowance, 0.0, 10.0, "allowance", "the stock left on the part, mm (default 0.5)");
  check(s.tolerance, 1e-4, 1.0, "tolerance", "mm (default 0.01)");
  check(s.rampAngleDeg, 0.5, 90.0, "ramp angle", "degrees (default 3)");
  check(s.clearance, 0.0, 1000.0, "clearance", "mm above the stock for links (default 5)");
  check(s.meshDeflection, 1e-3, 1.0, "mesh deflection", "mm (default 0.02)");
}
}  // namespace

double Cutter::profileRadius(double h) const {
  const double r = kind == CutterKind::Flat ? 0.0 : kind == CutterKind::Ball ? radius() : cornerRadius;
  if (h <= 0.0) return radius() - r;
  if (h >= r) return h <= stickOut ? radius() : 0.5 * holderDiameter;
  return radius() - r + std::sqrt(std::max(0.0, r * r - (r - h) * (r - h)));
}

std::string cutterKindName(CutterKind kind) {
  switch (kind) {
    case CutterKind::Flat: return "flat";
    case CutterKind::Torus: return "torus";
    case CutterKind::Ball: return "ball";
  }
  return "?";
}

std::string moveKindName(MoveKind kind) {
  switch (kind) {
    case MoveKind::Rapid: return "rapid";
    case MoveKind::Plunge: return "plunge";
    case MoveKind::Ramp: return "ramp";
    case MoveKind::Cut: return "cut";
    case MoveKind::Link: return "link";
  }
  return "?";
}

void checkCutter(const Cutter& c) {
  auto size = [](double value, const std::string& what) {
    if (!(value >= 0.1 && value <= 100.0))
      throw InputError("cutter " + what + " = " + number(value) + " mm is outside [0.1, 100] mm");
  };
  size(c.diameter, "diameter");
  size(c.fluteLength, "flute length");
  size(c.shankDiameter, "shank diameter");
  size(c.stickOut, "stick-out");
  size(c.holderDiameter, "holder diameter");
  size(c.holderLength, "holder length");
  if (c.kind == CutterKind::Torus && !(c.cornerRadius > 0.0 && c.cornerRadius < c.radius()))
    throw InputError("torus cutter: corner radius " + number(c.cornerRadius) + " mm must be in ]0, " +
                     number(c.radius()) + "[ mm (half the diameter); use a ball or a flat cutter otherwise");
  if (c.fluteLength > c.stickOut)
    throw InputError("cutter flute length " + number(c.fluteLength) + " mm is longer than its stick-out " +
                     number(c.stickOut) + " mm: the holder would cover the flutes");
  if (c.shankDiameter > c.holderDiameter)
    throw InputError("cutter shank Ø" + number(c.shankDiameter) + " mm is wider than its holder Ø" +
                     number(c.holderDiameter) + " mm");
}

SweepResult sweep(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part,
                  const TopoDS_Shape& stock, const SweepSettings& settings) {
  checkSettings(settings);
  if (partition.subVolumes.empty()) throw InputError("the partition has no sub-volumes to sweep");
  return Sweeper(partition, solid, part, stock, settings).run();
}

}  // namespace hsm::roughing
