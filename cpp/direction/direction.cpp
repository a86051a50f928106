#include "direction/direction.hpp"

#include "common/error.hpp"
#include "geometry/face_drop.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Eigen/Geometry>

#include <algorithm>
#include <deque>
#include <cmath>
#include <limits>
#include <sstream>

namespace hsm::direction {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
const double kSteepest = std::cos(89.0 * M_PI / 180.0);  // flatter than 89° from horizontal: machinable from above

Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Eigen::Vector3d toEigen(const gp_Dir& d) { return {d.X(), d.Y(), d.Z()}; }

std::string number(double x) {
  std::ostringstream text;
  text.precision(4);
  text << x;
  return text.str();
}

void validate(const CuttingConditions& c) {
  auto positive = [](double x, const char* what, const char* fix) {
    if (!(x > 0.0) || !std::isfinite(x)) throw InputError(std::string(what) + " = " + number(x) + " must be positive: " + fix);
  };
  positive(c.toolRadius, "tool radius", "give the ball's radius in mm");
  positive(c.scallop, "scallop height Sz", "e.g. 0.01 mm");
  positive(c.programmedFeed, "programmed feed", "give it in mm/s (mm/min in Python)");
  positive(c.spindleSpeed, "spindle speed", "give N in rev/s (rpm in Python)");
  if (c.teeth < 1) throw InputError("teeth Z = " + std::to_string(c.teeth) + ": a tool has at least one tooth");
}

// The feed marks of the programmed fz alone, fz²/(8·Ro), against Sz: above it only the directions where
// the machine slows down can keep the scallop.
std::string scallopTooSmall(const CuttingConditions& c) {
  const double fz = c.programmedFeedPerTooth(), marks = fz * fz / (8.0 * c.toolRadius);
  if (marks < c.scallop) return "";
  return "Sz = " + number(c.scallop) + " mm is too small for fz = " + number(fz) +
         " mm per tooth: the feed marks alone are fz²/(8·Ro) = " + number(marks) +
         " mm high; raise Sz or lower the feed per tooth";
}
}  // namespace

std::vector<SurfacePoint> sampleFace(const TopoDS_Face& face, int nu, int nv) {
  if (face.IsNull()) throw InputError("the face is null: pick a face");
  if (nu < 2 || nv < 2 || nu > kMaxGrid || nv > kMaxGrid)
    throw InputError("the sample grid " + std::to_string(nu) + " × " + std::to_string(nv) + " must be from 2 × 2 to " +
                     std::to_string(kMaxGrid) + " × " + std::to_string(kMaxGrid) + " points, e.g. 50 × 50");
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  const geometry::FaceDropper inside(face, Eigen::Vector3d::UnitZ());
  const double orientation = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
  std::vector<SurfacePoint> points;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / nu, v = v0 + (v1 - v0) * (j + 0.5) / nv;
      if (!inside.inside(u, v)) continue;
      GeomLProp_SLProps props(surface, u, v, 2, 1e-9);
      if (!props.IsNormalDefined() || !props.IsCurvatureDefined()) continue;
      SurfacePoint m;
      m.point = toEigen(props.Value());
      m.planArea = std::abs(props.D1U().Crossed(props.D1V()).Z()) * (u1 - u0) / nu * (v1 - v0) / nv;
      m.normal = orientation * toEigen(props.Normal());
      // OCCT's curvatures are positive when the centre of curvature lies on the side of its normal.
      m.k1 = orientation * props.MaxCurvature();
      m.k2 = orientation * props.MinCurvature();
      if (props.IsUmbilic()) {
        m.e1 = m.normal.unitOrthogonal();
        m.e2 = m.normal.cross(m.e1);
      } else {
        gp_Dir d1, d2;
        props.CurvatureDirections(d1, d2);
        m.e1 = toEigen(d1);
        m.e2 = toEigen(d2);
      }
      points.push_back(m);
    }
  // The tool is on the side the face's normal points to (as FreeCAD shows it: out of the material for a
  // face of a solid). A face that looks down is not turned over: a tool from above cannot reach it.
  return points;
}

Performance performance(const SurfacePoint& m, double thetaDeg, const CuttingConditions& c,
                        const kinematics::Dynamics& planAxes) {
  const double theta = thetaDeg * M_PI / 180.0;
  const Eigen::Vector3d d(std::cos(theta), std::sin(theta), 0.0), k = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d& n = m.normal;
  Performance p;
  // Transverse step (eq. 7-9): the step measured on the surface across d, for the scallop Sz.
  const Eigen::Vector3d dn = d.cross(n);
  const double cosBeta = dn.norm() > 1e-12 ? (dn.normalized().cross(d)).dot(k) : 0.0;
  // Radius of the path: the offset surface cut by the vertical plane through d.
  const Eigen::Vector3d planeNormal = d.cross(k);
  Eigen::Vector3d t = planeNormal.cross(n);
  double radius = kInfinity;
  if (t.norm() > 1e-12) {
    t.normalize();
    const double r = c.toolRadius;
    const double k1 = m.k1 / (1.0 - r * m.k1), k2 = m.k2 / (1.0 - r * m.k2);  // the offset's curvatures
    const double kn = k1 * std::pow(t.dot(m.e1), 2) + k2 * std::pow(t.dot(m.e2), 2);
    const double cosN = planeNormal.cross(t).normalized().dot(n);               // Meusnier
    const double kappa = std::abs(cosN) > 1e-12 ? kn / cosN : 0.0;
    if (std::abs(kappa) > 1e-15) radius = 1.0 / std::abs(kappa);
  }
  double reachable = c.programmedFeed;
  if (std::isfinite(radius)) {
    const kinematics::Dynamics feedLimit{planAxes.acceleration, planAxes.jerk, c.jerkLimitsFeed};
    reachable = std::min(reachable, kinematics::curvatureSpeed(radius, feedLimit));
  }
  p.pathRadius = radius;
  p.feedPerTooth = reachable / (c.teeth * c.spindleSpeed);
  const double room = 8.0 * c.scallop * c.toolRadius - p.feedPerTooth * p.feedPerTooth;
  p.transverseStep = room > 0.0 ? std::sqrt(room) * std::abs(cosBeta) : 0.0;
  p.fitness = p.transverseStep * p.feedPerTooth;
  return p;
}

DirectionResult optimalDirection(const TopoDS_Face& face, const CuttingConditions& c,
                                 const kinematics::MachineModel& machine, const DirectionSettings& s) {
  return optimalDirection(sampleFace(face, s.gridU, s.gridV), c, machine, s);
}

namespace {

// The time of parallel planes along `thetaDeg` over the points. A plane keeps one stepover from its
// neighbour: the smallest p1 along it. The plane through a point sees the points within half a point
// spacing of it across the planes (a window that slides with the point: fixed strips aliased with the
// sample grid, and directions along the grid's rows gave times 10 % off their neighbours'); the path
// length per plan area there is 1/that p1, stretched by the slope along d, at the point's real feed
// fz·Z·N. Each plane adds its run-outs and a reversal: their number is the integral of 1/p1 across the face.
// Infinite where a point gets no step. `steps` and `feeds`: p1 and the real fz of each point along d.
double planesTime(const std::vector<const SurfacePoint*>& points, double thetaDeg,
                  Eigen::Ref<const Eigen::VectorXd> steps, Eigen::Ref<const Eigen::VectorXd> feeds,
                  const CuttingConditions& c, const kinematics::Dynamics& planAxes) {
  const double theta = thetaDeg * M_PI / 180.0;
  const Eigen::Vector2d along(std::cos(theta), std::sin(theta)), across(-along.y(), along.x());
  const size_t n = points.size();
  double area = 0.0;
  std::vector<std::pair<double, size_t>> order(n);  // (position across the planes, point)
  for (size_t i = 0; i < n; ++i) {
    area += points[i]->planArea;
    order[i] = {across.dot(points[i]->point.head<2>()), i};
  }
  std::sort(order.begin(), order.end());
  const double width = std::max(std::sqrt(area / n), 1e-9);
  // Sliding-window minimum of p1 over |q_j − q_i| ≤ width / 2 (two pointers and a monotone deque).
  std::vector<double> planeStep(n, kInfinity);
  std::deque<size_t> window;  // indices into `order`, increasing p1
  size_t next = 0, first = 0;
  for (size_t k = 0; k < n; ++k) {
    const double q = order[k].first;
    while (next < n && order[next].first <= q + 0.5 * width) {
      const double p = steps(static_cast<Eigen::Index>(order[next].second));
      while (!window.empty() && steps(static_cast<Eigen::Index>(order[window.back()].second)) >= p) window.pop_back();
      window.push_back(next++);
    }
    while (order[first].first < q - 0.5 * width) ++first;
    while (window.front() < first) window.pop_front();
    planeStep[order[k].second] = steps(static_cast<Eigen::Index>(order[window.front()].second));
  }
  double time = 0.0, planes = 0.0;
  const double span = order.back().first - order.front().first + width;
  for (size_t i = 0; i < n; ++i) {
    const SurfacePoint& m = *points[i];
    if (!(planeStep[i] > 0.0)) return kInfinity;
    const double slope = along.dot(m.normal.head<2>()) / m.normal.z();
    const Eigen::Index at = static_cast<Eigen::Index>(i);
    time += m.planArea * std::sqrt(1.0 + slope * slope) / (feeds(at) * c.teeth * c.spindleSpeed) / planeStep[i];
    planes += span * (m.planArea / area) / planeStep[i];  // ∫ dq / p1, each point weighted by its area
  }
  const double perPlane = 2.0 * c.toolRadius / c.programmedFeed + kinematics::stopAndGoLoss(c.programmedFeed, planAxes);
  return time + planes * perPlane;
}

// Symmetric faces give the same α* at θ and 180° − θ: the tie goes to the direction nearest the X axis,
// then to the smaller angle, so that the answer does not flip between feeds or platforms.
double tieBrokenOptimum(const std::vector<double>& anglesDeg, const std::vector<double>& rate, double alpha) {
  double chosen = 0.0, chosenFromAxis = kInfinity;
  for (size_t j = 0; j < rate.size(); ++j) {
    if (rate[j] < alpha * (1.0 - 1e-9)) continue;
    const double fromAxis = std::min(anglesDeg[j], 180.0 - anglesDeg[j]);
    if (fromAxis < chosenFromAxis - 1e-12) {
      chosen = anglesDeg[j];
      chosenFromAxis = fromAxis;
    }
  }
  return chosen;
}

}  // namespace

DirectionResult optimalDirection(const std::vector<SurfacePoint>& all, const CuttingConditions& c,
                                 const kinematics::MachineModel& machine, const DirectionSettings& s) {
  validate(c);
  kinematics::checkMachine(machine);
  const kinematics::Dynamics planAxes = kinematics::slowestPlanAxes(machine);
  if (!(s.angleStepDeg >= kMinAngleStepDeg && s.angleStepDeg <= 1.0))
    throw InputError("the angle step " + number(s.angleStepDeg) + "° must be in [" + number(kMinAngleStepDeg) +
                     "°, 1°]: directions at 1° or finer");
  const double work = double(all.size()) * std::lround(180.0 / s.angleStepDeg);
  if (work > kMaxEvaluations)
    throw InputError(std::to_string(all.size()) + " points × " + std::to_string(std::lround(180.0 / s.angleStepDeg)) +
                     " directions = " + number(work) + " evaluations exceed the limit " + number(kMaxEvaluations) +
                     ": use a coarser grid or angle step (50 × 50 points at 1° take 38 ms)");
  if (!(s.reportAlpha > 0.0 && s.reportAlpha <= 1.0)) throw InputError("the reported α must be in (0, 1]");
  DirectionResult result;
  std::vector<const SurfacePoint*> points;
  long steep = 0, tooTight = 0;
  for (const SurfacePoint& m : all) {
    if (m.normal.z() <= kSteepest) {
      ++steep;
    } else if (1.0 - c.toolRadius * std::max(m.k1, m.k2) <= 0.0) {
      ++tooTight;
    } else {
      points.push_back(&m);
    }
  }
  if (steep) result.warnings.push_back(std::to_string(steep) + " point(s) vertical or undercut (facing 89° or more from the tool axis) left out: parallel planes from above cannot finish them");
  if (tooTight) result.warnings.push_back(std::to_string(tooTight) + " point(s) concave tighter than the ball left out: a smaller tool is needed there");
  const long down = std::count_if(all.begin(), all.end(), [](const SurfacePoint& m) { return m.normal.z() < -kSteepest; });
  if (points.empty() && down > 0 && down + steep >= static_cast<long>(all.size()) && tooTight == 0)
    throw InputError("the face looks down (" + std::to_string(down) + " of its " + std::to_string(all.size()) +
                     " points face below the horizontal): a tool along +Z cannot reach it, in any direction; finish "
                     "it from a second setup with the part turned over (a face of a surface model whose normal "
                     "points the wrong way: reverse it)");
  if (points.empty())
    throw InputError("no point of the face can be finished by parallel planes with this tool (" + std::to_string(steep) +
                     " vertical or undercut, " + std::to_string(tooTight) +
                     " tighter than the ball): use a Z-level strategy or a smaller ball");

  const int count = static_cast<int>(std::lround(180.0 / s.angleStepDeg));
  for (int j = 0; j < count; ++j) result.anglesDeg.push_back(180.0 * j / count);
  result.rate.assign(count, kInfinity);
  const Eigen::Index n = static_cast<Eigen::Index>(points.size());
  result.points.resize(n, 3);
  Eigen::MatrixXd steps(n, count), feeds(n, count);  // p1 and the real fz, per point and direction
  std::vector<double> fitness(count);
  for (Eigen::Index i = 0; i < n; ++i) {
    double best = 0.0;
    int at = 0;
    for (int j = 0; j < count; ++j) {
      const Performance p = performance(*points[i], result.anglesDeg[j], c, planAxes);
      steps(i, j) = p.transverseStep;
      feeds(i, j) = p.feedPerTooth;
      fitness[j] = p.fitness;
      if (fitness[j] > best) {
        best = fitness[j];
        at = j;
      }
    }
    result.points.row(i) = points[i]->point.transpose();
    result.bestAngleDeg.push_back(result.anglesDeg[at]);
    result.fitnessMax.push_back(best);
    if (best <= 0.0) continue;
    for (int j = 0; j < count; ++j) {
      result.rate[j] = std::min(result.rate[j], fitness[j] / best);
    }
  }
  const bool anyFitness = std::any_of(result.fitnessMax.begin(), result.fitnessMax.end(), [](double g) { return g > 0; });
  const std::string marks = scallopTooSmall(c);
  if (!anyFitness) throw InputError(marks.empty() ? "no direction gives a transverse step at any point" : marks);
  if (!marks.empty()) result.warnings.push_back(marks + " (only where the machine slows down is Sz kept)");
  for (double& r : result.rate)
    if (!std::isfinite(r)) r = 0.0;
  result.alpha = *std::max_element(result.rate.begin(), result.rate.end());
  result.optimalAngleDeg = tieBrokenOptimum(result.anglesDeg, result.rate, result.alpha);
  for (int j = 0; j < count; ++j)
    result.predictedTime.push_back(planesTime(points, result.anglesDeg[j], steps.col(j), feeds.col(j), c, planAxes));
  std::vector<double> speed(count);  // 1/T, so that the same tie rule picks the least time
  for (int j = 0; j < count; ++j) speed[j] = result.predictedTime[j] > 0.0 ? 1.0 / result.predictedTime[j] : 0.0;
  result.fastestAngleDeg = tieBrokenOptimum(result.anglesDeg, speed, *std::max_element(speed.begin(), speed.end()));
  const double worst = *std::min_element(result.rate.begin(), result.rate.end());
  result.allTie = result.alpha - worst < 1e-9;
  if (result.allTie)
    result.warnings.push_back("every direction performs the same (a flat face): choose the direction by path length");
  result.reportedAlpha = std::min(result.alpha, s.reportAlpha);
  for (int j = 0; j < count; ++j)
    if (result.rate[j] >= result.reportedAlpha - 1e-12) result.acceptableDeg.push_back(result.anglesDeg[j]);
  return result;
}

double beamAlgorithmAlpha(const std::vector<double>& rate, double start, double step, double precision) {
  auto intersectionEmpty = [&](double alpha) {
    return std::none_of(rate.begin(), rate.end(), [&](double r) { return r >= alpha; });
  };
  double alpha = intersectionEmpty(start) ? 0.0 : start;
  while (step > precision) {
    if (!intersectionEmpty(alpha + step)) {
      alpha += step;  // the beams still meet: demand more of every direction
    } else {
      step *= 0.5;    // the intersection emptied: come back and take a smaller step
    }
  }
  return alpha;
}

}  // namespace hsm::direction
