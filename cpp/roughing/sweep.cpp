// Slicings swept by contour-parallel passes (sweep.hpp): each level laid flat (planes as they are, cylinders
// unrolled), its region, shadow and domain in Clipper's integer plane, its offsets, then entries, loops and
// links as tool moves.
#include "roughing/sweep.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/flat.hpp"
#include "roughing/grown_cutter.hpp"
#include "roughing/projection.hpp"
#include "roughing/push_out.hpp"
#include "roughing/step_up.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>

namespace hsm::roughing {

namespace {
constexpr int kMaxRings = 10000;
constexpr double kOverhang = 0.1;  // of the diameter: the outer pass goes this far past the slice's outline
constexpr double kFloorSlack = 0.005;  // mm
constexpr int kHeightBands = 8;  // layers of the part under the corner radius, each kept out by its own width
// The push-out of a level's boundary: from points this far apart (true mm), this much beyond
// the clearance the passes' chords and the push's own steps take.
constexpr double kPushSpacing = 0.25, kPushMargin = 0.01;

// A slice as its levels see it: its main level (the tip on its far side), its near side, its region laid
// flat and where the tool's centre may go in it before the part is kept out.
// A point of the stock a previous operation left, as a slice sees it: its height, where it lies flat, and
// the plane's scales there.
struct RestPoint {
  double height;
  cl::IntPoint flat;
  Eigen::Vector2d scales;
};

struct Slice {
  int subVolume = 0;
  double tip = 0.0, top = 0.0;  // heights along the axis: the main level's tip and the slice's near side
  std::vector<Band> bands;      // of the part's heights relative to the tip, each with its keep-out (grown_cutter)
  cl::Paths region, inner;
  Window window;
  std::vector<RestPoint> rest;  // rest roughing: the stock left within the slice's heights
};

struct Level {
  int subVolume = 0;
  double tip = 0.0, top = 0.0;  // heights along the axis: the tip's surface and the slice's near side
  cl::Paths region, domain;
  cl::Paths cleared;             // the slice's main domain, cut: clear from its tip to the slice's near side
  std::vector<FlatPass> passes;  // outside in
  bool intermediate = false;     // between a slice's main level and its near side: cuts what that left
};

class Sweeper {
public:
  Sweeper(const Partition& partition, const RemovalSolid& solid, const TopoDS_Shape& part, const TopoDS_Shape& stock,
          const SweepSettings& settings)
      : partition_(partition), settings_(settings), report_(settings.progress, "sweep"),
        projection_(projectionOf(partition, solid)), partMesh_(geometry::meshFacesAfresh(part, settings.meshDeflection)) {
    report_(0.0);  // each step of the set-up, the slices and their levels: a GUI repaints and takes Cancel between
    const geometry::TriangleMesh stockMesh = geometry::meshFaces(stock, std::max(0.05, settings.meshDeflection));
    report_(0.0);
    double high = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : stockMesh.vertices) high = std::max(high, projection_->height(p));
    safeHeight_ = high + settings.clearance;
    projection_->setReach(settings.cutter.radius() + settings.allowance + settings.meshDeflection + settings.tolerance);
    for (const Eigen::Vector3d& p : settings.rest.points) restHeights_.push_back(projection_->height(p));
    if (settings.pushOutMost > 0.0)
      pushPart_ = std::make_unique<PartTriangles>(partMesh_);
  }

  SweepResult run() {
    const int count = static_cast<int>(partition_.subVolumes.size());
    // From the crossable face inwards: S5's slices are numbered from the hub, the tool comes from the skin.
    const bool fromLast = partition_.strategy == Strategy::HubOffsets;
    for (int k = 0; k < count; ++k) {
      const double from = double(k) / count, to = double(k + 1) / count;
      report_(from);
      const int i = fromLast ? count - 1 - k : k;
      const Slice slice = makeSlice(i);
      sweepSlice(slice, [&](double within) { report_(from + (to - from) * within); });
    }
    if (!result_.moves.empty()) retract();
    report_(1.0);
    return std::move(result_);
  }

private:
  // The main level, then the intermediate ones from the near side down: each cuts, between its height and the
  // level above it, what the main level's domain left (the domain grows with the height).
  void sweepSlice(const Slice& slice, const std::function<void(double)>& reportWithin) {
    std::map<double, cl::Paths> domains;
    const DomainAt domainAt = [&](double h) -> const cl::Paths& {
      auto found = domains.find(h);
      if (found == domains.end()) found = domains.emplace(h, domainOf(slice, h)).first;
      return found->second;
    };
    const cl::Paths& main = domainAt(slice.tip);
    const std::vector<double> heights =
        stepUpHeights(slice.tip, slice.top, domainAt, settings_.stepUpMinimum, settings_.stepUpScallop, settings_.tolerance);
    if (main.empty() && heights.empty()) {
      result_.warnings.push_back("slice " + std::to_string(partition_.subVolumes[slice.subVolume].slice) +
                                 ": the tool fits nowhere in it (narrower than the tool, or under the part)");
      return;
    }
    // Rest roughing cuts only where the tool reaches the stock left, entering and leaving outside it.
    const bool rest = !settings_.rest.points.empty();
    const double lead = 0.5 * settings_.cutter.radius();
    Level level = levelOf(slice, slice.tip, main, main);
    const cl::Paths wanted = rest ? restWithin(slice, slice.tip, slice.top) : cl::Paths{};
    level.passes = passesBeyond(ringsOf(main, slice.tip), {}, 0.0, lead, 0.5, settings_.tolerance, rest ? &wanted : nullptr);
    bool down = false;  // the tool is at a cut inside the slice, not retracted
    const double levels = double(heights.size() + 1);
    const auto inLevel = [&](double index) {  // a level's passes report their share of it
      return [&reportWithin, index, levels](double within) { reportWithin((index + within) / levels); };
    };
    reportWithin(0.0);
    if (!level.passes.empty()) sweepLevel(level, down, inLevel(0.0));
    reportWithin(1.0 / levels);
    double above = slice.top;
    // An intermediate level's domain lies in the one's above it, whose passes its entries come down from.
    cl::Paths domainAbove;
    for (size_t index = 0; index < heights.size(); ++index) {
      const double h = heights[index];
      domainAbove = index == 0 ? domainAt(h) : boolean(cl::ctIntersection, domainAt(h), domainAbove);
      Level up = levelOf(slice, h, domainAbove, main);
      // The level above cut its whole domain, which holds this one's: entries come down from there.
      up.top = std::exchange(above, h);
      up.intermediate = true;
      // Only where the band beyond the main domain is wider than the staircase allowed: a narrower one leaves
      // no thicker step across the wall.
      const cl::Paths wantedHere = rest ? restWithin(slice, h, up.top) : cl::Paths{};
      up.passes = passesBeyond(ringsOf(up.domain, h), main, settings_.stepUpScallop, lead, 0.5, settings_.tolerance,
                               rest ? &wantedHere : nullptr);
      if (!up.passes.empty()) sweepLevel(up, down, inLevel(double(index + 1)));
      reportWithin(double(index + 2) / levels);
    }
    if (down) retract();
  }

  // Where the tool's centre at a level reaches the rest stock that lies between heights `from` and `to`: each
  // point's cube grown by the tool's radius, laid flat (a square over the plane's scales there), united.
  cl::Paths restWithin(const Slice& slice, double from, double to) const {
    const double s = settings_.rest.spacing, reach = settings_.cutter.radius() + 0.5 * s;
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const RestPoint& p : slice.rest)
      if (p.height >= from - 0.5 * s && p.height <= to + 0.5 * s) {
        x0 = std::min(x0, double(p.flat.X)), x1 = std::max(x1, double(p.flat.X));
        y0 = std::min(y0, double(p.flat.Y)), y1 = std::max(y1, double(p.flat.Y));
      }
    if (!(x1 >= x0)) return {};
    // Cells of the spacing where the plane is most stretched; the points' squares marked on them.
    const double cell = s / projection_->largestScale() * kScale;
    const double margin = reach / std::max(projection_->smallestScale(), 0.05) * kScale + cell;
    x0 -= margin, y0 -= margin, x1 += margin, y1 += margin;
    const long nx = static_cast<long>((x1 - x0) / cell) + 1, ny = static_cast<long>((y1 - y0) / cell) + 1;
    if (nx * ny > 50'000'000)
      throw InputError("rest roughing: the stock left spans " + std::to_string(nx * ny) + " cells of " +
                       number(s) + " mm laid flat: use a larger rest spacing");
    std::vector<char> marked(static_cast<size_t>(nx * ny), 0);
    for (const RestPoint& p : slice.rest) {
      if (!(p.height >= from - 0.5 * s && p.height <= to + 0.5 * s)) continue;
      const double hx = reach / std::max(p.scales.x(), 0.05) * kScale, hy = reach / std::max(p.scales.y(), 0.05) * kScale;
      const long i0 = std::max(0L, long((double(p.flat.X) - hx - x0) / cell)), i1 = std::min(nx - 1, long((double(p.flat.X) + hx - x0) / cell));
      const long j0 = std::max(0L, long((double(p.flat.Y) - hy - y0) / cell)), j1 = std::min(ny - 1, long((double(p.flat.Y) + hy - y0) / cell));
      for (long j = j0; j <= j1; ++j) std::fill(marked.begin() + j * nx + i0, marked.begin() + j * nx + i1 + 1, 1);
    }
    cl::Paths rectangles;  // each row's runs of marked cells
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i) {
        if (!marked[static_cast<size_t>(j * nx + i)]) continue;
        long k = i;
        while (k + 1 < nx && marked[static_cast<size_t>(j * nx + k + 1)]) ++k;
        const cl::cInt a = cl::cInt(x0 + i * cell), b = cl::cInt(x0 + (k + 1) * cell);
        const cl::cInt c = cl::cInt(y0 + j * cell), d = cl::cInt(y0 + (j + 1) * cell);
        rectangles.push_back({{a, c}, {b, c}, {b, d}, {a, d}});
        i = k;
      }
    return united(rectangles);
  }

  Level levelOf(const Slice& slice, double tip, const cl::Paths& domain, const cl::Paths& cleared) const {
    Level level;
    level.subVolume = slice.subVolume;
    level.tip = tip, level.top = slice.top;
    level.region = slice.region;
    level.domain = domain;
    level.cleared = cleared;
    return level;
  }

  // The height of the slice's slicing surface (sweep.hpp: the near side, or S5's far side).
  double surfaceHeight(const SubVolume& sub) const {
    if (sub.surface.kind == SurfaceKind::Cylinder) return sub.surface.radius;
    if (sub.surface.kind == SurfaceKind::Plane) return projection_->height(sub.surface.origin);
    if (sub.axisPoints.empty()) throw ComputationError("slice " + std::to_string(sub.slice) + " has no point on its surface");
    return projection_->height(sub.axisPoints.front());
  }

  Slice makeSlice(int index) {
    const SubVolume& sub = partition_.subVolumes[index];
    Slice slice;
    slice.subVolume = index;
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
      // tip stays the allowance above it, and as much more as a concave hub rises under the tool's bottom.
      projection_->setLevel(surface, mesh);
      slice.top = std::min(surface + partition_.step, high);
      slice.tip = std::max(surface, surface - sub.surface.offset + settings_.allowance + grown().floorLift() +
                                        settings_.meshDeflection);
      slice.top = std::max(slice.top, slice.tip + settings_.tolerance);
    } else {
      slice.top = surface;
      slice.tip = std::max(slice.top - partition_.step, low);
      projection_->setLevel(slice.tip, mesh);
      raiseOverFloor(slice);
    }
    // One plane for all the slice's levels (the intermediate ones compare their domains with the main one's):
    // its scales are the main level's, the tip surface that has the least room.
    projection_->setLevel(slice.tip, mesh);
    slice.bands = grown().bands(kHeightBands, kFloorSlack, settings_.meshDeflection + settings_.tolerance,
                                projection_->convexity());
    slice.region = projectedUnion(mesh, *projection_, -std::numeric_limits<double>::infinity());
    // Only the part near the region matters: within the tool's radius, the allowance and a margin of it.
    const double margin = (radius + settings_.allowance + settings_.meshDeflection + 1.0) / projection_->smallestScale();
    slice.window = windowAround(slice.region, 1.5 * margin);
    slice.inner = offset(slice.region, -(radius - kOverhang * settings_.cutter.diameter) / projection_->largestScale(),
                         settings_.tolerance);
    const double spacing = settings_.rest.spacing;
    for (size_t k = 0; k < restHeights_.size(); ++k) {
      const double h = restHeights_[k];
      if (!(h >= slice.tip - radius - spacing && h <= slice.top + spacing)) continue;
      const Eigen::Vector3d& p = settings_.rest.points[k];
      slice.rest.push_back({h, projection_->plane(p), projection_->scalesAt(p)});
    }
    return slice;
  }

  // Where the tool's centre may go with its tip at `tip`: the slice's inner region less the part's keep-out,
  // layer by layer above the tip (the slice's bands): the part from the allowance under the tip up is kept as
  // far from the centre as the tool, grown by the allowance, is wide there (a torus's corner is narrower than
  // its flutes; on a concave surface a point off the axis stands higher along it), and the mesh's deflection
  // and the offsets' arc tolerance (their chords cut inside the arcs) more. That keep-out is on the safe side
  // (the widest over each band, bins of scales): the boundary is then pushed out to the real clearance, the
  // allowance, the mesh's deflection and the passes' chords, exact on the part's triangles (push_out.hpp).
  cl::Paths domainOf(const Slice& slice, double tip) const {
    std::vector<Band> bands = slice.bands;
    for (Band& band : bands) band.from += tip, band.to += tip;
    const cl::Paths keepOut = keepOutOf(partMesh_, *projection_, bands, slice.window, settings_.tolerance, slice.inner);
    const cl::Paths domain = boolean(cl::ctDifference, slice.inner, keepOut);
    if (!pushPart_) return domain;
    PushSettings push;
    push.clearance = settings_.allowance + settings_.meshDeflection + settings_.tolerance + kPushMargin;
    push.lowest = slice.bands.front().from;
    push.most = settings_.pushOutMost;
    push.spacing = kPushSpacing;
    return pushedOut(domain, slice.inner, tip, *projection_, *pushPart_, settings_.cutter, push);
  }

  // The domain's boundary, then its offsets inwards every radial step, never farther apart than the engagement
  // asked where the plane is most stretched; then, while the middle of the last ring lies beyond the reach of
  // the tool's bottom from it (an island the rings would leave), rings between.
  Rings ringsOf(const cl::Paths& domain, double tip) const {
    Rings rings;
    const double scale = projection_->largestScale();
    const double step = settings_.radialEngagement * settings_.cutter.diameter / scale;
    const double reach = (settings_.cutter.radius() - 0.5 * settings_.cutter.corner()) / scale;
    auto add = [&](cl::Paths ring, double depth) {
      simplify(ring, settings_.tolerance);
      if (ring.empty()) return false;
      densify(ring, projection_->maxSegment(tip, settings_.tolerance));
      rings.loops.push_back(std::move(ring));
      rings.depths.push_back(depth);
      return true;
    };
    for (int k = 0; k < kMaxRings && add(k == 0 ? domain : offset(domain, -k * step, settings_.tolerance), k * step); ++k) {
    }
    for (int extra = 0; !rings.loops.empty() && extra < 4; ++extra) {
      const double depth = rings.depths.back();
      if (offset(domain, -(depth + reach), settings_.tolerance).empty()) break;
      double more = step;
      while (more > 0.05 && offset(domain, -(depth + more), settings_.tolerance).empty()) more *= 0.5;
      if (!add(offset(domain, -(depth + more), settings_.tolerance), depth + more)) break;
    }
    return rings;
  }

  // The cutter grown by the allowance on the level the projection is set to.
  GrownCutter grown() const {
    return GrownCutter(settings_.cutter, settings_.allowance, projection_->concavity(), projection_->concavityAcross());
  }

  // A face of the part parallel to the slicing surface within the allowance under the tip (a floor: a plane
  // parallel to S1's, the hub under S4's offsets of a skin that follows it): the tip stays the allowance above
  // it, or the whole floor would be out of reach. Parallel within 2°: a curved floor's facets are tilted from
  // its normal by the mesh's deflection.
  void raiseOverFloor(Slice& slice) const {
    const double parallel = std::cos(2.0 * M_PI / 180.0);
    double floor = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3i& t : partMesh_.triangles) {
      const Eigen::Vector3d& p0 = partMesh_.vertices[t[0]];
      const Eigen::Vector3d n = (partMesh_.vertices[t[1]] - p0).cross(partMesh_.vertices[t[2]] - p0);
      if (!(n.norm() > 0.0) || n.normalized().dot(projection_->axisAt(p0)) < parallel) continue;
      double h = -std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k) h = std::max(h, projection_->height(partMesh_.vertices[t[k]]));
      if (h > slice.tip - settings_.allowance - 1e-9 && h < slice.tip + settings_.allowance) floor = std::max(floor, h);
    }
    // As S5's tip over its hub: a curved floor's mesh is within its deflection of it, and the lift is of second
    // order in the distance from the axis (a plane's facets lie on it).
    const double lift = grown().floorLift();
    const double raised = floor + settings_.allowance + (lift > 0.0 ? lift + settings_.meshDeflection : 0.0);
    if (std::isfinite(floor) && raised < slice.top) slice.tip = raised;
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

  // Down to the loop's start: a plunge where the tool's disk is clear of the slice's material (or `cleared`
  // says the levels below took it out), else a ramp along the loop from the slice's near side. The full loop
  // is then cut from where the tool reaches the level.
  Arrival enter(const Level& level, const cl::Path& loop, size_t start, bool cleared) {
    const Eigen::Vector3d first = projection_->point(loop[start], level.top + 1.0);
    if (result_.moves.empty()) add(MoveKind::Rapid, projection_->point(loop[start], safeHeight_), -1);
    else if (projection_->height(result_.moves.back().tip) > safeHeight_ - 1e-9) travel(loop[start]);
    add(MoveKind::Rapid, first, level.subVolume);
    const bool clear = cleared || (!insidePaths(loop[start], level.region) &&
                                   distanceToBoundary(loop[start], level.region) >= settings_.cutter.radius());
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
  void cutLoop(const Level& level, const cl::Path& loop, const Arrival& from, int ring, double depth) {
    Pass pass{level.subVolume, ring, {}, true, level.intermediate, depth};
    for (size_t k = 1; k <= loop.size(); ++k) {
      const Eigen::Vector3d p = projection_->point(loop[(from.index + k) % loop.size()], level.tip);
      add(MoveKind::Cut, p, level.subVolume);
      pass.points.push_back(p);
    }
    add(MoveKind::Cut, projection_->point(from.point, level.tip), level.subVolume);
    result_.passes.push_back(std::move(pass));
  }

  // An open pass from its first point (where the tool is) to its last.
  void cutOpen(const Level& level, const cl::Path& path, int ring, double depth) {
    Pass pass{level.subVolume, ring, {projection_->point(path.front(), level.tip)}, false, level.intermediate, depth};
    for (size_t k = 1; k < path.size(); ++k) {
      const Eigen::Vector3d p = projection_->point(path[k], level.tip);
      add(MoveKind::Cut, p, level.subVolume);
      pass.points.push_back(p);
    }
    result_.passes.push_back(std::move(pass));
  }

  // The passes ring by ring from the outside in, each time the nearest one to the tool (a loop from its nearest
  // point, an open pass from its start), linked at the level where the straight move stays in the domain, or
  // from another level of the slice where it stays in what the main level cleared; else the tool retracts.
  // `down`: the tool is at a cut of this slice (it stays so at the end).
  void sweepLevel(const Level& level, bool& down, const std::function<void(double)>& reportWithin) {
    bool entered = down;
    std::vector<bool> done(level.passes.size(), false);
    for (size_t n = 0; n < level.passes.size(); ++n) {
      reportWithin(double(n) / double(level.passes.size()));
      int ring = std::numeric_limits<int>::max();
      for (size_t l = 0; l < level.passes.size(); ++l)
        if (!done[l]) ring = std::min(ring, level.passes[l].ring);
      size_t best = 0, bestPoint = 0;
      double bestDistance = std::numeric_limits<double>::infinity();
      cl::IntPoint here;
      bool placed = entered;
      if (entered) here = projection_->plane(result_.moves.back().tip);
      for (size_t l = 0; l < level.passes.size(); ++l) {
        if (done[l] || level.passes[l].ring != ring) continue;
        const FlatPass& candidate = level.passes[l];
        if (!placed) here = candidate.points.front(), placed = true;
        for (size_t p = 0; p < (candidate.closed ? candidate.points.size() : 1); ++p) {
          const double d = std::hypot(double(candidate.points[p].X - here.X), double(candidate.points[p].Y - here.Y));
          if (d < bestDistance) bestDistance = d, best = l, bestPoint = p;
        }
      }
      done[best] = true;
      const FlatPass& pass = level.passes[best];
      if (pass.points.size() < (pass.closed ? 3u : 2u)) continue;
      Arrival from{bestPoint, pass.points[bestPoint]};
      const double height = entered ? projection_->height(result_.moves.back().tip) : level.tip;
      const bool atLevel = std::abs(height - level.tip) < 1e-9;
      if (entered && segmentInside(here, from.point, atLevel ? level.domain : level.cleared, settings_.tolerance)) {
        link(here, height, from.point, level.tip, level.subVolume);
      } else {
        if (entered) retract();
        from = enter(level, pass.points, bestPoint, !pass.closed);
      }
      entered = true;
      if (pass.closed) cutLoop(level, pass.points, from, pass.ring, pass.depth);
      else cutOpen(level, pass.points, pass.ring, pass.depth);
    }
    down = entered;
  }

  // A straight move in the flat passes from one height to another (points added where the surface bends).
  void link(const cl::IntPoint& from, double fromHeight, const cl::IntPoint& to, double toHeight, int subVolume) {
    const double length = std::hypot(double(to.X - from.X), double(to.Y - from.Y)) / kScale;
    const double longest = projection_->maxSegment(std::min(fromHeight, toHeight), settings_.tolerance);
    const int pieces = std::isfinite(longest) ? std::max(1, static_cast<int>(std::ceil(length / longest))) : 1;
    for (int k = 1; k <= pieces; ++k) {
      const double f = double(k) / pieces;
      add(MoveKind::Link, projection_->point({static_cast<cl::cInt>(from.X + (to.X - from.X) * f),
                                              static_cast<cl::cInt>(from.Y + (to.Y - from.Y) * f)},
                                             fromHeight + (toHeight - fromHeight) * f), subVolume);
    }
  }

  const Partition& partition_;
  const SweepSettings& settings_;
  ProgressReporter report_;
  std::unique_ptr<Projection> projection_;
  geometry::TriangleMesh partMesh_;  // within the mesh deflection
  std::unique_ptr<PartTriangles> pushPart_;  // the same triangles in a grid, for the push-out (when on)
  std::vector<double> restHeights_;  // of the rest stock's points (NaN where the projection has none)
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
  // Below 0.005 mm the impeller alone is 260,000 triangles or more (906,000 at 0.001): the keep-out and the
  // push-out read them all, for less than the chords (0.01) leave.
  check(s.meshDeflection, 0.005, 1.0, "mesh deflection", "mm the part's triangles may stray from its faces (default 0.05)");
  if (s.stepUpMinimum != 0.0) check(s.stepUpMinimum, 0.1, 100.0, "step-up minimum", "mm between levels, or 0 for none (default 1)");
  check(s.stepUpScallop, 0.01, 10.0, "step-up scallop", "mm of the staircase left across a wall (default 0.25)");
  check(s.pushOutMost, 0.0, 10.0, "push-out", "mm a level's boundary may move towards the part (0: off; default 1.5)");
  if (!s.rest.points.empty()) {
    check(s.rest.spacing, 0.01, 20.0, "rest stock spacing", "mm between its points (the removal simulation's)");
    for (const Eigen::Vector3d& p : s.rest.points)
      if (!p.allFinite()) throw InputError("rest stock: a point is not finite (NaN or infinite coordinates)");
  }
}

// Each slice's intermediate levels are bounded by the minimum step between them.
void checkStepUp(const SweepSettings& s, const Partition& partition) {
  constexpr double kMaxLevelsPerSlice = 64.0;
  if (s.stepUpMinimum > 0.0 && partition.step / s.stepUpMinimum > kMaxLevelsPerSlice)
    throw InputError("step-up minimum " + number(s.stepUpMinimum) + " mm would allow " +
                     number(std::floor(partition.step / s.stepUpMinimum)) + " levels in a slice of " +
                     number(partition.step) + " mm, more than " + number(kMaxLevelsPerSlice) +
                     ": use a minimum of at least " + number(partition.step / kMaxLevelsPerSlice) + " mm");
}
}  // namespace

double Cutter::corner() const {
  return kind == CutterKind::Flat ? 0.0 : kind == CutterKind::Ball ? radius() : cornerRadius;
}

double Cutter::profileRadius(double h) const {
  const double r = corner();
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
  checkStepUp(settings, partition);
  return Sweeper(partition, solid, part, stock, settings).run();
}

}  // namespace hsm::roughing
