#include "roughing/push_out.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"
#include "roughing/flat.hpp"
#include "roughing/tool_distance.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hsm::roughing {

namespace {
constexpr double kCell = 2.0;          // mm: the grid's cubes
constexpr long kMostPoints = 1000000;  // boundary points of one level: bounded work
constexpr int kMostTries = 24;         // cutter positions tried per point
constexpr double kLeastStep = 0.02;    // true mm: the finest a push is resolved
constexpr double kGatherSlack = 1.0;   // true mm a point may be from where the triangles were gathered
constexpr double kSteepest = 0.1;      // flat mm a push may change per flat mm along the boundary (6°)
constexpr double kPinhole = 1.0;       // true mm²: the largest hole of the pushed outline filled

// A pushed point, laid flat.
cl::IntPoint pushedPoint(const cl::IntPoint& q, const Eigen::Vector2d& n, double t) {
  return {q.X + static_cast<cl::cInt>(std::llround(n.x() * t * kScale)), q.Y + static_cast<cl::cInt>(std::llround(n.y() * t * kScale))};
}

// One boundary point's push: the cutter stands at the point moved `t` flat mm along the normal.
class Push {
public:
  Push(const PartTriangles& part, const Projection& projection, const CutterBody& body, double radius, double tip,
       const PushSettings& settings)
      : part_(part), projection_(projection), body_(body), radius_(radius), tip_(tip), settings_(settings),
        seen_(part.mesh.triangles.size(), -1) {}

  // How far (flat mm, at most `most`) the point q moves along the unit flat normal n: sphere tracing, each step
  // the room left over how fast a move can close it (the axis turns as the point moves: the cutter's top
  // moves more than its tip), never finer than kLeastStep; a step that comes too close halves the rest.
  double distance(const cl::IntPoint& q, const Eigen::Vector2d& n, double most) {
    const double lipschitz = prepare(q, n, most);
    const double leastStep = kLeastStep / projection_.largestScale();
    double t = 0.0, room = clearanceAt(at(0.0)) - settings_.clearance, limit = most;
    bool blocked = false;  // whether the limit is a position found too close
    for (int k = 0; k < kMostTries && room >= 0.0 && limit - t > 0.5 * leastStep; ++k) {
      double next = std::min(limit, t + std::max(leastStep, room / lipschitz));
      if (blocked) next = std::min(next, t + 0.5 * (limit - t));
      const double there = clearanceAt(at(next)) - settings_.clearance;
      if (there >= 0.0) t = next, room = there;
      else limit = next, blocked = true;
    }
    return room >= 0.0 ? t : 0.0;
  }

  // The point q and its normal n taken, the triangles near it chosen: those a cutter within `most` flat mm of
  // it (and two spacings more, for the chords to its neighbours' places) may come too close to, nearest first.
  // Returns how many true mm the cutter moves at most per flat mm.
  double prepare(const cl::IntPoint& q, const Eigen::Vector2d& n, double most) {
    from_ = q, normal_ = n;
    const double scale = projection_.largestScale();
    const double lipschitz = scale * (1.0 + turnRate(kLeastStep / scale) * body_.length);
    const double reach = lipschitz * (most + 2.0 * settings_.spacing);
    farEnough_ = settings_.clearance + reach;
    tip0_ = projection_.point(q, tip_), top0_ = tip0_ + projection_.axisAtPlane(q, tip_) * body_.length;
    // Neighbouring points share their triangles: gathered once for a few of them, with room to spare.
    if (!(reach <= gatheredReach_ - kGatherSlack && (tip0_ - gatheredTip_).norm() <= kGatherSlack &&
          (top0_ - gatheredTop_).norm() <= kGatherSlack))
      gather(q, reach + 2.0 * kGatherSlack);
    nearest_.clear();
    for (int t : gathered_) {
      const double bound = reachBound(t, tip0_, top0_);
      if (bound < farEnough_) nearest_.push_back({t, bound});
    }
    std::sort(nearest_.begin(), nearest_.end(), [](const Near& a, const Near& b) { return a.bound < b.bound; });
    return lipschitz;
  }

  // Whether the cutter at q (near the point last prepared) keeps the clearance from the triangles.
  bool clearAt(const cl::IntPoint& q) const { return leastDistance(q, settings_.clearance) >= settings_.clearance; }

private:
  struct Near {
    int triangle;
    double bound;  // from below, the distance from the cutter at the prepared point to the triangle
  };

  // From below, the distance from the cutter standing on the axis tip–top to triangle t: the cutter lies
  // within its radius of that axis, the triangle within its bounding sphere.
  double reachBound(int t, const Eigen::Vector3d& tip, const Eigen::Vector3d& top) const {
    return segmentDistance(part_.grid.centre(t), tip, top) - part_.grid.boundingRadius(t) - radius_;
  }

  cl::IntPoint at(double t) const { return pushedPoint(from_, normal_, t); }

  // Radians the axis turns per flat mm along the normal.
  double turnRate(double step) const {
    const Eigen::Vector3d a = projection_.axisAtPlane(at(0.0), tip_), b = projection_.axisAtPlane(at(step), tip_);
    return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) / step;
  }

  // The triangles that a cutter within `reach` true mm of the position at q may come nearer than the clearance.
  void gather(const cl::IntPoint& q, double reach) {
    gathered_.clear();
    gatheredTip_ = tip0_, gatheredTop_ = top0_, gatheredReach_ = reach;
    const Eigen::Vector3d axis = projection_.axisAtPlane(q, tip_);
    // Under the tip, nothing lower than the clearance and the reach matters (the cutter's bottom is its tip).
    const double low = std::clamp(settings_.lowest, -(settings_.clearance + reach), 0.0);
    part_.grid.near(tip0_ + axis * low, top0_, radius_ + settings_.clearance + reach, seen_, stamp_++,
                    [&](int t) { gathered_.push_back(t); });
  }

  double clearanceAt(const cl::IntPoint& q) const { return leastDistance(q, farEnough_); }

  // The least distance from the cutter at q to the chosen triangles, or `enough` where all are farther: they
  // are taken nearest first, and none is looked at once its bound, less how far the cutter moved from the
  // prepared point, is beyond what was found.
  double leastDistance(const cl::IntPoint& q, double enough) const {
    const Eigen::Vector3d tip = projection_.point(q, tip_), axis = projection_.axisAtPlane(q, tip_);
    const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u), top = tip + axis * body_.length;
    // Every point of the cutter's axis moved at most as far as its ends did.
    const double moved = std::max((tip - tip0_).norm(), (top - top0_).norm());
    double least = enough;
    Eigen::Vector3d local[3];
    for (const Near& near : nearest_) {
      if (near.bound - moved >= least) break;
      if (reachBound(near.triangle, tip, top) >= least) continue;
      const Eigen::Vector3i& corners = part_.mesh.triangles[near.triangle];
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d d = part_.mesh.vertices[corners[k]] - tip;
        local[k] = Eigen::Vector3d(u.dot(d), v.dot(d), axis.dot(d));
      }
      least = std::min(least, cutterDistance(local, body_, settings_.lowest));
      if (least < settings_.clearance && enough <= settings_.clearance) break;  // too close is all clearAt asks
    }
    return least;
  }

  const PartTriangles& part_;
  const Projection& projection_;
  const CutterBody& body_;
  double radius_, tip_;
  const PushSettings& settings_;
  std::vector<int> seen_;
  int stamp_ = 0;
  std::vector<int> gathered_;  // triangles
  Eigen::Vector3d gatheredTip_ = Eigen::Vector3d::Zero(), gatheredTop_ = Eigen::Vector3d::Zero();
  double gatheredReach_ = -1.0;
  std::vector<Near> nearest_;
  Eigen::Vector3d tip0_ = Eigen::Vector3d::Zero(), top0_ = Eigen::Vector3d::Zero();
  double farEnough_ = 0.0;
  cl::IntPoint from_;
  Eigen::Vector2d normal_ = Eigen::Vector2d::UnitX();
};

void checkSettings(const PushSettings& settings) {
  if (!(settings.clearance >= 0.0 && settings.clearance < 100.0))
    throw InputError("push-out: clearance " + number(settings.clearance) + " mm is outside [0, 100[ mm");
  if (!(settings.most > 0.0 && settings.most <= 10.0))
    throw InputError("push-out: the farthest move " + number(settings.most) + " mm is outside ]0, 10] mm");
  if (!(settings.spacing >= 0.01 && settings.spacing <= 10.0))
    throw InputError("push-out: spacing " + number(settings.spacing) + " mm is outside [0.01, 10] mm");
}

// The outward unit normal (laid flat) at each point of a closed path: Clipper's outer paths turn
// anticlockwise and its holes clockwise, so the domain is on the left of every edge and (dy, −dx) leaves it.
std::vector<Eigen::Vector2d> outwardNormals(const cl::Path& path) {
  const size_t n = path.size();
  std::vector<Eigen::Vector2d> normals(n);
  auto edge = [&](size_t i) {
    const cl::IntPoint& a = path[i];
    const cl::IntPoint& b = path[(i + 1) % n];
    const Eigen::Vector2d d(double(b.Y - a.Y), -double(b.X - a.X));
    return d.norm() > 0.0 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d(Eigen::Vector2d::Zero());
  };
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d sum = edge((i + n - 1) % n) + edge(i);
    normals[i] = sum.norm() > 1e-9 ? Eigen::Vector2d(sum.normalized()) : edge(i);
  }
  return normals;
}

// Pushes of neighbouring points, flat mm, each path's in turn: `pushes` holds them all, path after path.
using Pushes = std::vector<double>;

// Where the rays of two neighbouring points cross (the boundary turns in), each is cut at the crossing.
void cutCrossings(const cl::Paths& boundary, const std::vector<std::vector<Eigen::Vector2d>>& normals, Pushes& pushes) {
  size_t k0 = 0;
  for (size_t p = 0; p < boundary.size(); k0 += boundary[p].size(), ++p) {
    const size_t n = boundary[p].size();
    for (size_t i = 0; i < n; ++i) {
      const size_t j = (i + 1) % n;
      const Eigen::Vector2d& a = normals[p][i];
      const Eigen::Vector2d& b = normals[p][j];
      const Eigen::Vector2d d(double(boundary[p][j].X - boundary[p][i].X) / kScale,
                              double(boundary[p][j].Y - boundary[p][i].Y) / kScale);
      const double det = b.x() * a.y() - a.x() * b.y();
      if (std::abs(det) < 1e-12) continue;
      const double s = (b.x() * d.y() - b.y() * d.x()) / det, u = (a.x() * d.y() - a.y() * d.x()) / det;
      double& ti = pushes[k0 + i];
      double& tj = pushes[k0 + j];
      if (s > 0.0 && s <= ti && u > 0.0 && u <= tj) ti = s, tj = u;
    }
  }
}

// Pushes that change faster along the boundary than kSteepest (flat mm per flat mm) are lowered to it: a point
// held back (too close at its start, or a chord too close) would leave a notch, and the pushes' own
// resolution a saw tooth, each a sharp turn where the machine slows down. Lowering a push only shrinks what
// the domain gains, so what was clear stays clear.
void limitSlopes(const cl::Paths& boundary, Pushes& pushes) {
  size_t k0 = 0;
  for (const cl::Path& path : boundary) {
    const size_t n = path.size();
    auto apart = [&](size_t i, size_t j) {
      return std::hypot(double(path[j].X - path[i].X), double(path[j].Y - path[i].Y)) / kScale;
    };
    for (int round = 0; round < 2; ++round)  // twice round: what the last point lowers reaches the first
      for (size_t m = 0; m < n; ++m) {
        const size_t i = m, j = (m + 1) % n;                  // forwards
        const size_t b = n - 1 - m, a = (b + n - 1) % n;      // backwards
        pushes[k0 + j] = std::min(pushes[k0 + j], pushes[k0 + i] + kSteepest * apart(i, j));
        pushes[k0 + a] = std::min(pushes[k0 + a], pushes[k0 + b] + kSteepest * apart(a, b));
      }
    k0 += n;
  }
}

// A triangle of Clipper points turned anticlockwise; empty where it has no area.
cl::Path anticlockwise(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
  cl::Path triangle{a, b, c};
  const double twice = double(b.X - a.X) * double(c.Y - a.Y) - double(b.Y - a.Y) * double(c.X - a.X);
  if (std::abs(twice) < 1.0) return {};
  if (twice < 0.0) std::reverse(triangle.begin(), triangle.end());
  return triangle;
}
// The straight edge between two neighbouring pushed places cuts inside the arc the clearance follows round a
// convex edge of the part: where it is longer than the spacing, the cutter is tried along it, every spacing,
// and both pushes are halved while it comes too close anywhere (after six halvings, none).
void keepChordsClear(const cl::Paths& boundary, const std::vector<std::vector<Eigen::Vector2d>>& normals,
                     Pushes& pushes, const Projection& projection, const PartTriangles& part, const CutterBody& body,
                     double radius, double tip, double most, const PushSettings& settings) {
  struct Pair {
    size_t path, i, j, ki, kj;
  };
  std::vector<Pair> pairs;
  size_t k0 = 0;
  for (size_t p = 0; p < boundary.size(); k0 += boundary[p].size(), ++p)
    for (size_t i = 0; i < boundary[p].size(); ++i) {
      const size_t j = (i + 1) % boundary[p].size();
      pairs.push_back({p, i, j, k0 + i, k0 + j});
    }
  const double step = settings.spacing / projection.largestScale();
  for (int round = 0; round < 7; ++round) {
    std::vector<char> tooClose(pairs.size(), 0);
    parallelChunks(static_cast<long>(pairs.size()), settings.threads, 64, [&](long from, long to) {
      Push push(part, projection, body, radius, tip, settings);
      for (long m = from; m < to; ++m) {
        const Pair& pair = pairs[static_cast<size_t>(m)];
        if (pushes[pair.ki] == 0.0 && pushes[pair.kj] == 0.0) continue;
        const cl::IntPoint a = pushedPoint(boundary[pair.path][pair.i], normals[pair.path][pair.i], pushes[pair.ki]);
        const cl::IntPoint b = pushedPoint(boundary[pair.path][pair.j], normals[pair.path][pair.j], pushes[pair.kj]);
        const double length = std::hypot(double(b.X - a.X), double(b.Y - a.Y)) / kScale;
        if (length <= 1.25 * step) continue;
        push.prepare(boundary[pair.path][pair.i], normals[pair.path][pair.i], most + length);
        const int pieces = static_cast<int>(std::ceil(length / step));
        for (int k = 1; k < pieces && !tooClose[static_cast<size_t>(m)]; ++k) {
          const double f = double(k) / pieces;
          if (!push.clearAt({a.X + static_cast<cl::cInt>(f * double(b.X - a.X)), a.Y + static_cast<cl::cInt>(f * double(b.Y - a.Y))}))
            tooClose[static_cast<size_t>(m)] = 1;
        }
      }
    });
    bool any = false;
    for (size_t m = 0; m < pairs.size(); ++m)
      if (tooClose[m]) {
        any = true;
        for (size_t k : {pairs[m].ki, pairs[m].kj}) pushes[k] = round < 6 ? 0.5 * pushes[k] : 0.0;
      }
    if (!any) break;
  }
}

// Whether the cutter keeps the clearance at a hole's corners and its middle.
bool clearThroughout(const cl::Path& hole, Push& push) {
  double x = 0.0, y = 0.0, span = 0.0;
  for (const cl::IntPoint& q : hole) x += double(q.X), y += double(q.Y);
  const cl::IntPoint middle{cl::cInt(x / hole.size()), cl::cInt(y / hole.size())};
  for (const cl::IntPoint& q : hole) span = std::max(span, std::hypot(double(q.X - middle.X), double(q.Y - middle.Y)) / kScale);
  push.prepare(middle, Eigen::Vector2d::UnitX(), span);
  return push.clearAt(middle) && std::all_of(hole.begin(), hole.end(), [&](const cl::IntPoint& q) { return push.clearAt(q); });
}

// Where pushes of points a few apart cross, the pushed outline folds over itself and the triangles' union
// leaves pinholes the domain did not have (a hole of the part's own is at least the cutter's disk). Each hole
// smaller than kPinhole is filled when the cutter keeps the clearance at its corners and its middle.
void fillPinholes(cl::Paths& united, const PartTriangles& part, const Projection& projection,
                  const CutterBody& body, double radius, double tip, const PushSettings& settings) {
  const double largest = kPinhole / (projection.largestScale() * projection.largestScale()) * kScale * kScale;
  Push push(part, projection, body, radius, tip, settings);
  const auto pinhole = [&](const cl::Path& path) {
    return !path.empty() && !cl::Orientation(path) && -cl::Area(path) <= largest && clearThroughout(path, push);
  };
  united.erase(std::remove_if(united.begin(), united.end(), pinhole), united.end());
}
}  // namespace

PartTriangles::PartTriangles(geometry::TriangleMesh triangles) : mesh(std::move(triangles)), grid(mesh, kCell) {}

cl::Paths pushedOut(const cl::Paths& domain, const cl::Paths& within, double tip, const Projection& projection,
                    const PartTriangles& part, const Cutter& cutter, const PushSettings& settings) {
  checkSettings(settings);
  if (domain.empty()) return {};
  cl::Paths boundary = domain;
  densify(boundary, settings.spacing / projection.largestScale());
  struct Point {
    size_t path, index;
  };
  std::vector<Point> points;
  std::vector<std::vector<Eigen::Vector2d>> normals;
  for (size_t p = 0; p < boundary.size(); ++p) {
    normals.push_back(outwardNormals(boundary[p]));
    for (size_t i = 0; i < boundary[p].size(); ++i) points.push_back({p, i});
    if (static_cast<long>(points.size()) > kMostPoints)
      throw InputError("push-out: more than " + std::to_string(kMostPoints) + " boundary points at " +
                       number(settings.spacing) + " mm: use a larger spacing");
  }
  // Each point's push, flat mm; the points in chunks that the threads take in turn.
  std::vector<double> pushes(points.size(), 0.0);
  const CutterBody body(cutter, cutter.stickOut);
  const double most = settings.most / projection.largestScale();
  parallelChunks(static_cast<long>(points.size()), settings.threads, 64, [&](long from, long to) {
    Push push(part, projection, body, cutter.radius(), tip, settings);
    for (long k = from; k < to; ++k) {
      const Point& p = points[static_cast<size_t>(k)];
      const Eigen::Vector2d& n = normals[p.path][p.index];
      if (n.norm() > 0.5) pushes[static_cast<size_t>(k)] = push.distance(boundary[p.path][p.index], n, most);
    }
  });
  cutCrossings(boundary, normals, pushes);
  limitSlopes(boundary, pushes);
  keepChordsClear(boundary, normals, pushes, projection, part, body, cutter.radius(), tip, most, settings);
  // Between two neighbouring points and their pushed places: two triangles that grow the domain.
  cl::Paths grown = domain;
  size_t k = 0;
  for (size_t p = 0; p < boundary.size(); ++p) {
    const cl::Path& path = boundary[p];
    const size_t n = path.size();
    std::vector<cl::IntPoint> moved(n);
    for (size_t i = 0; i < n; ++i, ++k) {
      moved[i] = pushedPoint(path[i], normals[p][i], pushes[k]);
    }
    for (size_t i = 0; i < n; ++i) {
      const size_t j = (i + 1) % n;
      if (moved[i] == path[i] && moved[j] == path[j]) continue;
      for (cl::Path triangle : {anticlockwise(path[i], path[j], moved[j]), anticlockwise(path[i], moved[j], moved[i])})
        if (!triangle.empty()) grown.push_back(std::move(triangle));
    }
  }
  cl::Paths united = roughing::united(grown);
  fillPinholes(united, part, projection, body, cutter.radius(), tip, settings);
  return boolean(cl::ctIntersection, united, within);
}

}  // namespace hsm::roughing
