// S3's setup direction: the fixed tool axis from which a straight tool reaches the most of the volume without
// crossing the part (after Heo et al. 2008). Accessibility by height maps: along a direction d, a point of the
// volume is reachable when nothing of the part lies above it (the highest part surface over its cell of the
// plane normal to d is below it).
#include "roughing/roughing.hpp"
#include "roughing/dexel.hpp"
#include "geometry/bounds.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/text.hpp"
#include "geometry/mesh.hpp"
#include "roughing/rays.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <gp_Lin.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepTools.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {

constexpr long kMaxPoints = 400000;       // points of the volume sampled: the memory and time bound
constexpr double kMinResolutionDeg = 0.5;

// Points of the solid on a grid of `spacing` (cell centres inside it), column by column: a vertical line through
// each column meets the solid's faces, and the stretches between entries and exits hold its points.
std::vector<Eigen::Vector3d> gridPoints(const TopoDS_Shape& solid, double spacing) {
  Bnd_Box box = geometry::exactBounds(solid);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  const double cells = std::ceil((x1 - x0) / spacing) * std::ceil((y1 - y0) / spacing) * std::ceil((z1 - z0) / spacing);
  if (cells > 50.0 * kMaxPoints)
    throw InputError("a setup grid of " + number(spacing) + " mm over this volume has " + number(cells) +
                     " cells: use a coarser grid (at least " +
                     number(spacing * std::cbrt(cells / (50.0 * kMaxPoints))) + " mm)");
  const RayCaster lines(solid, 1e-7);
  std::vector<Eigen::Vector3d> points;
  for (double x = x0 + 0.5 * spacing; x < x1; x += spacing)
    for (double y = y0 + 0.5 * spacing; y < y1; y += spacing) {
      std::vector<double> hits;
      for (const RayHit& hit : lines.all(gp_Lin(gp_Pnt(x, y, z0 - 1.0), gp::DZ()), 0.0, z1 - z0 + 2.0))
        hits.push_back(z0 - 1.0 + hit.w);
      if (hits.size() < 2) continue;
      for (size_t k = 0; k + 1 < hits.size(); k += 2)
        for (double z = z0 + 0.5 * spacing; z < z1; z += spacing)
          if (z > hits[k] && z < hits[k + 1]) points.emplace_back(x, y, z);
      if (static_cast<long>(points.size()) > kMaxPoints)
        throw InputError("the setup grid of " + number(spacing) + " mm puts more than " + std::to_string(kMaxPoints) +
                         " points in the volume: use a coarser grid");
    }
  return points;
}

// A face's outward normal (of the volume) at the middle of its parameters, or zero where it is undefined.
Eigen::Vector3d outwardNormal(const TopoDS_Face& face) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  BRepAdaptor_Surface surface(face);
  BRepLProp_SLProps props(surface, 0.5 * (u0 + u1), 0.5 * (v0 + v1), 1, 1e-9);
  if (!props.IsNormalDefined()) return Eigen::Vector3d::Zero();
  gp_Dir n = props.Normal();
  if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
  return {n.X(), n.Y(), n.Z()};
}

// Where the tool may come from: the area-weighted mean outward normal of the crossable faces, and the
// directions a CAM programmer tries first, seeded into the search so that a narrow optimum (a slot's axis:
// every direction off the plane of its walls is worse) is not missed between the coarse directions: the
// normals of the crossable faces, and the normals into the volume of the facing_crossable faces (a floor is
// best reached square to it).
struct ToolSides {
  Eigen::Vector3d mean = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> seeds;
};

ToolSides toolSides(const RemovalSolid& s) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(s.solid, TopAbs_FACE, faces);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  ToolSides sides;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const FaceClass c = s.faceClasses[static_cast<size_t>(i - 1)];
    if (c == FaceClass::NotCrossable) continue;
    const Eigen::Vector3d n = outwardNormal(TopoDS::Face(faces(i)));
    if (n.isZero()) continue;
    if (c == FaceClass::Crossable) sum += s.faceAreas[static_cast<size_t>(i - 1)] * n;
    sides.seeds.push_back(c == FaceClass::Crossable ? n : Eigen::Vector3d(-n));
  }
  if (sum.norm() > 1e-12) sides.mean = sum.normalized();
  sides.seeds.push_back(sides.mean);
  return sides;
}

// Directions within `cone` of `centre`, every `spacing` (rings of directions about it), hemisphere-bounded
// about the solid's mean outward normal by the caller's choice of centre and cone.
std::vector<Eigen::Vector3d> cap(const Eigen::Vector3d& centre, double cone, double spacing) {
  const Eigen::Vector3d u = centre.unitOrthogonal(), w = centre.cross(u);
  std::vector<Eigen::Vector3d> directions;
  for (double polar = 0.0; polar <= cone + 1e-9; polar += spacing) {
    const int around = polar < 1e-9 ? 1 : std::max(1, static_cast<int>(std::round(2.0 * M_PI * std::sin(polar) / spacing)));
    for (int k = 0; k < around; ++k) {
      const double azimuth = 2.0 * M_PI * k / around;
      directions.push_back(std::cos(polar) * centre + std::sin(polar) * (std::cos(azimuth) * u + std::sin(azimuth) * w));
    }
  }
  return directions;
}

// Share of the points reachable along d: a height map of the part's triangles (their highest point over each
// cell of the plane normal to d, cells of `cell` mm) against the points' heights.
double reachShare(const geometry::TriangleMesh& part, const std::vector<Eigen::Vector3d>& points,
                  const Eigen::Vector3d& d, double cell) {
  const Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  double a0 = std::numeric_limits<double>::infinity(), b0 = a0, a1 = -a0, b1 = -a0;
  for (const Eigen::Vector3d& p : points) {
    a0 = std::min(a0, e1.dot(p)), a1 = std::max(a1, e1.dot(p));
    b0 = std::min(b0, e2.dot(p)), b1 = std::max(b1, e2.dot(p));
  }
  const int na = static_cast<int>((a1 - a0) / cell) + 1, nb = static_cast<int>((b1 - b0) / cell) + 1;
  std::vector<double> top(static_cast<size_t>(na) * nb, -std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3i& t : part.triangles) {
    Eigen::Vector3d q[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& v = part.vertices[t[k]];
      q[k] = {(e1.dot(v) - a0) / cell, (e2.dot(v) - b0) / cell, d.dot(v)};
    }
    const int i0 = std::max(0, static_cast<int>(std::floor(std::min({q[0].x(), q[1].x(), q[2].x()}))));
    const int i1 = std::min(na - 1, static_cast<int>(std::floor(std::max({q[0].x(), q[1].x(), q[2].x()}))));
    const int j0 = std::max(0, static_cast<int>(std::floor(std::min({q[0].y(), q[1].y(), q[2].y()}))));
    const int j1 = std::min(nb - 1, static_cast<int>(std::floor(std::max({q[0].y(), q[1].y(), q[2].y()}))));
    // The triangle's height at the centres of the cells it covers (a wall seen edge-on covers none: it shadows
    // nothing but itself).
    auto raise = [&](int i, int j, double height) {
      double& h = top[static_cast<size_t>(j) * na + i];
      h = std::max(h, height);
    };
    const double det = (q[1].x() - q[0].x()) * (q[2].y() - q[0].y()) - (q[2].x() - q[0].x()) * (q[1].y() - q[0].y());
    if (std::abs(det) < 1e-12) continue;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double x = i + 0.5 - q[0].x(), y = j + 0.5 - q[0].y();
        const double b1 = (x * (q[2].y() - q[0].y()) - y * (q[2].x() - q[0].x())) / det;
        const double b2 = (y * (q[1].x() - q[0].x()) - x * (q[1].y() - q[0].y())) / det;
        if (b1 < -1e-9 || b2 < -1e-9 || b1 + b2 > 1.0 + 1e-9) continue;
        raise(i, j, q[0].z() + b1 * (q[1].z() - q[0].z()) + b2 * (q[2].z() - q[0].z()));
      }
  }
  long reached = 0;
  for (const Eigen::Vector3d& p : points) {
    const int i = std::clamp(static_cast<int>((e1.dot(p) - a0) / cell), 0, na - 1);
    const int j = std::clamp(static_cast<int>((e2.dot(p) - b0) / cell), 0, nb - 1);
    if (d.dot(p) >= top[static_cast<size_t>(j) * na + i]) ++reached;
  }
  return points.empty() ? 0.0 : double(reached) / double(points.size());
}

// The volume's grid points and the part's mesh, as every reach count needs them.
struct ReachProblem {
  std::vector<Eigen::Vector3d> points;
  geometry::TriangleMesh mesh;
};

// The points of the rest stock inside the solid (on its tri-dexel model at the grid's spacing), every k-th
// where there are more than the search may take.
std::vector<Eigen::Vector3d> restPointsIn(const TopoDS_Shape& solid, const RestStock& rest, double spacing) {
  const geometry::TriangleMesh mesh = geometry::meshFacesAfresh(solid, std::min(0.05, 0.25 * spacing));
  TriDexel model(mesh.bounds(), std::min(spacing, 0.5), kMaxPoints * 20);
  model.fill(mesh);
  std::vector<Eigen::Vector3d> inside;
  for (const Eigen::Vector3d& p : rest.points)
    if (model.inside(p)) inside.push_back(p);
  const size_t every = 1 + inside.size() / static_cast<size_t>(kMaxPoints);
  std::vector<Eigen::Vector3d> kept;
  for (size_t i = 0; i < inside.size(); i += every) kept.push_back(inside[i]);
  return kept;
}

ReachProblem reachProblem(const RemovalSolid& solid, const TopoDS_Shape& part, const PartitionSettings& settings) {
  if (!(settings.setupGrid > 0.0) || !std::isfinite(settings.setupGrid))
    throw InputError("the setup grid " + number(settings.setupGrid) + " mm must be positive, e.g. 2 mm");
  ReachProblem problem;
  // Rest roughing: what the operations before left in this volume; where they left nothing, the volume.
  if (!settings.rest.points.empty()) problem.points = restPointsIn(solid.solid, settings.rest, settings.setupGrid);
  if (problem.points.empty()) problem.points = gridPoints(solid.solid, settings.setupGrid);
  if (problem.points.empty())
    throw InputError("the setup grid of " + number(settings.setupGrid) + " mm puts no point inside the volume: use a finer grid");
  Bnd_Box box = geometry::exactBounds(part);
  problem.mesh = geometry::meshFacesAfresh(part, std::max(1e-3, 5e-3 * std::sqrt(box.SquareExtent())));
  return problem;
}

}  // namespace

double reachableShare(const RemovalSolid& solid, const TopoDS_Shape& part, const Eigen::Vector3d& direction,
                      const PartitionSettings& settings) {
  if (!(direction.norm() > 1e-12) || !direction.allFinite())
    throw InputError("the tool direction must be a non-zero vector, e.g. (0, 0, 1)");
  const ReachProblem problem = reachProblem(solid, part, settings);
  return reachShare(problem.mesh, problem.points, direction.normalized(), settings.setupGrid);
}

std::pair<Eigen::Vector3d, double> setupDirection(const RemovalSolid& solid, const TopoDS_Shape& part,
                                                  const PartitionSettings& settings) {
  if (!(settings.setupResolutionDeg >= kMinResolutionDeg && settings.setupResolutionDeg <= 45.0))
    throw InputError("the setup directions' resolution " + number(settings.setupResolutionDeg) + "° must be from " +
                     number(kMinResolutionDeg) + "° to 45°, e.g. 5°");
  const ReachProblem problem = reachProblem(solid, part, settings);
  const std::vector<Eigen::Vector3d>& points = problem.points;
  const geometry::TriangleMesh& mesh = problem.mesh;
  const ToolSides sides = toolSides(solid);
  // Coarse to fine: the hemisphere about the mean every 16° and the seeds; then cones about the best few so
  // far (a ridge of equal reach has several), halving the spacing down to the resolution. Ties go to the
  // direction nearest the mean: the least tilt from where the tool comes in.
  struct Candidate {
    Eigen::Vector3d direction;
    double share;
  };
  auto better = [&](const Candidate& a, const Candidate& b) {
    if (std::abs(a.share - b.share) > 1e-12) return a.share > b.share;
    return a.direction.dot(sides.mean) > b.direction.dot(sides.mean);
  };
  constexpr size_t kCentres = 4;
  const double finest = settings.setupResolutionDeg * M_PI / 180.0;
  double spacing = std::max(finest, 16.0 * M_PI / 180.0);
  std::vector<Eigen::Vector3d> directions = cap(sides.mean, 0.5 * M_PI, spacing);
  for (const Eigen::Vector3d& seed : sides.seeds)
    if (seed.dot(sides.mean) > -1e-9) directions.push_back(seed);
  std::vector<Candidate> ranked;
  ProgressReporter reporter(settings.progress, "setup direction search");
  const int passes = 1 + static_cast<int>(std::ceil(std::log2(std::max(1.0, spacing / finest)) - 1e-9));
  for (int pass = 0;; ++pass) {
    reporter(double(pass) / passes);
    std::vector<double> share(directions.size(), 0.0);
    parallelSlices(static_cast<long>(directions.size()), settings.threads, 2, [&](long from, long to) {
      for (long i = from; i < to; ++i)
        share[static_cast<size_t>(i)] = reachShare(mesh, points, directions[static_cast<size_t>(i)], settings.setupGrid);
    });
    for (size_t i = 0; i < directions.size(); ++i) ranked.push_back({directions[i].normalized(), share[i]});
    std::sort(ranked.begin(), ranked.end(), better);
    if (spacing <= finest * (1.0 + 1e-9)) break;
    const double cone = spacing;
    spacing = std::max(finest, 0.5 * spacing);
    directions.clear();
    std::vector<Eigen::Vector3d> centres;
    for (const Candidate& c : ranked) {
      if (centres.size() == kCentres) break;
      const bool apart = std::all_of(centres.begin(), centres.end(),
                                     [&](const Eigen::Vector3d& e) { return e.dot(c.direction) < std::cos(0.5 * cone); });
      if (!apart) continue;
      centres.push_back(c.direction);
      for (const Eigen::Vector3d& d : cap(c.direction, cone, spacing))
        if (d.dot(sides.mean) > -1e-9) directions.push_back(d);
    }
    ranked.resize(std::min(ranked.size(), kCentres * 4));
  }
  reporter(1.0);
  return {ranked.front().direction, ranked.front().share};
}

}  // namespace hsm::roughing
