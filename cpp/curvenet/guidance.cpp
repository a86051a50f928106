// The 4-step method of the guidance-curve paper (§4.3), steps 1 to 3.
//
// Step 2 as we read it: the inflection points of the two guides, projected on the machining direction,
// become plane positions; between two of them the planes are spaced by min(P0, R/2), R the smallest plan
// radius of the guides there (at least minStep), so that a small radius gets one plane every ~30° of turn
// instead of "very few points or no points".
#include "curvenet/curvenet.hpp"
#include "curvenet/layout.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/bspline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::curvenet {

using detail::Layout;

namespace {

constexpr int kCurvatureSamples = 2000;

struct GuideShape {
  double minRadius = 0.0;  // 3D, mm
  bool straight = false;
  std::vector<double> inflectionStations;
  std::vector<std::pair<double, double>> planRadiusByStation;  // (d·x, plan radius)
};

GuideShape measureGuide(const Handle(Geom_BSplineCurve)& curve, const detail::Frame& frame, double tolerance) {
  GuideShape shape;
  const auto report = geometry::analyzeCurve(curve, frame.axis, tolerance, 1000.0, kCurvatureSamples);
  shape.straight = report.straight;
  shape.minRadius = shape.straight ? std::numeric_limits<double>::infinity() : report.minRadius;
  for (double t : report.inflectionParameters) {
    const gp_Pnt p = curve->Value(t);
    shape.inflectionStations.push_back(frame.direction.dot(Eigen::Vector3d(p.X(), p.Y(), p.Z())));
  }
  for (const auto& c : geometry::sampleCurvature(curve, frame.axis, kCurvatureSamples)) {
    const double radius = c.planCurvature != 0.0 ? 1.0 / std::abs(c.planCurvature)
                                                 : std::numeric_limits<double>::infinity();
    shape.planRadiusByStation.emplace_back(frame.direction.dot(c.point), radius);
  }
  return shape;
}

double smallestPlanRadius(const GuideShape& guide, double from, double to) {
  double radius = std::numeric_limits<double>::infinity();
  for (const auto& [s, r] : guide.planRadiusByStation)
    if (s >= from && s <= to) radius = std::min(radius, r);
  return radius;
}

// Plane positions adapted to two guides over [from, to] (see the comment at the top).
std::vector<double> adaptedStations(const GuideShape& g1, const GuideShape& g2, double from, double to,
                                    const GuidanceSettings& settings, GuidanceReport& report) {
  std::vector<double> keys{from, to};
  for (const GuideShape* g : {&g1, &g2})
    for (double s : g->inflectionStations)
      if (s > from + settings.minStep && s < to - settings.minStep) {
        keys.push_back(s);
        report.inflectionStations.push_back(s);
      }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end(), [&](double a, double b) { return b - a < settings.minStep; }),
             keys.end());
  keys.back() = to;
  std::vector<double> stations{from};
  for (size_t i = 0; i + 1 < keys.size(); ++i) {
    const double a = keys[i], b = keys[i + 1];
    const double radius = std::min(smallestPlanRadius(g1, a, b), smallestPlanRadius(g2, a, b));
    const double step = std::clamp(0.5 * radius, settings.minStep, settings.net.step);
    const auto piece = detail::evenStations(a, b, step);
    stations.insert(stations.end(), piece.begin() + 1, piece.end());
    for (size_t j = 1; j < piece.size(); ++j) {
      const double spacing = piece[j] - piece[j - 1];
      report.smallestStep = report.smallestStep == 0.0 ? spacing : std::min(report.smallestStep, spacing);
      report.largestStep = std::max(report.largestStep, spacing);
    }
  }
  return stations;
}

void checkSettings(const GuidanceSettings& settings) {
  detail::checkRatio(settings.kMedian, "K of the median");
  detail::checkRatio(settings.k, "K of the intermediate curves");
  if (!(settings.minStep >= kMinStep) || settings.minStep > settings.net.step)
    throw InputError("smallest step " + mm(settings.minStep) + " must be at least " + mm(kMinStep) +
                     " and at most the initial step P0 (" + mm(settings.net.step) + "), e.g. 0.5 mm");
}

// The smallest distance between a curve and its target in planes where the boundaries are at least the
// minimum gap apart.
double smallestGap(const Layout& layout, const PointArray& curve, const PointArray& target,
                   const std::vector<double>& stations) {
  const PointArray b1 = layout.boundary(1).cut(stations).points;
  const PointArray b2 = layout.boundary(2).cut(stations).points;
  double gap = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < curve.rows(); ++i)
    if ((b2.row(i) - b1.row(i)).norm() >= layout.settings().minGap)
      gap = std::min(gap, (target.row(i) - curve.row(i)).norm());
  return gap;
}

}  // namespace

GuidanceResult guidanceCurves(const Boundaries& boundaries, const GuidanceSettings& settings) {
  checkSettings(settings);
  GuidanceResult result;
  CurveNet& net = result.net;
  GuidanceReport& report = result.report;
  const double tolerance = settings.net.fitTolerance;

  // Step 2 for the median's guides (the boundaries), then step 1: the median.
  const Layout probe(boundaries, settings.net, net.warnings);
  const auto [from, to] = probe.commonExtent();
  const GuideShape shape1 = measureGuide(probe.boundary(1).curve(), probe.frame(), tolerance);
  const GuideShape shape2 = measureGuide(probe.boundary(2).curve(), probe.frame(), tolerance);
  std::vector<std::string> ignored;  // the probe already reported what the boundaries have to say
  const Layout layout(boundaries, settings.net, ignored,
                      adaptedStations(shape1, shape2, from, to, settings, report));
  const NetCurve b1 = detail::boundaryCurve(layout, 1), b2 = detail::boundaryCurve(layout, 2);
  NetCurve median = detail::buildCurve(layout, b1, b2, settings.kMedian, layout.stations(), net.warnings);
  median.role = CurveRole::Median;
  median.label = "Cmed";
  const GuideShape medianShape = measureGuide(median.curve, layout.frame(), tolerance);

  // Step 3: in each half, one curve with K from the guide whose smallest radius is the larger.
  NetCurve halves[2];
  bool built[2] = {false, false};
  for (int side = 1; side <= 2; ++side) {
    const NetCurve& boundary = side == 1 ? b1 : b2;
    const GuideShape& boundaryShape = side == 1 ? shape1 : shape2;
    GuidanceHalf& half = side == 1 ? report.half1 : report.half2;
    const bool boundaryStarts = boundaryShape.minRadius >= medianShape.minRadius;
    const NetCurve& start = boundaryStarts ? boundary : median;
    const NetCurve& target = boundaryStarts ? median : boundary;
    half.start = start.label;
    half.target = target.label;
    half.startMinRadius = boundaryStarts ? boundaryShape.minRadius : medianShape.minRadius;
    half.targetMinRadius = boundaryStarts ? medianShape.minRadius : boundaryShape.minRadius;
    half.skipped = boundaryShape.straight && medianShape.straight;
    if (half.skipped) continue;
    const auto stations = adaptedStations(boundaryShape, medianShape, from, to, settings, report);
    NetCurve curve = detail::buildCurve(layout, start, target, settings.k, stations, net.warnings);
    curve.net = side;
    curve.rank = 1;
    curve.label = "C" + std::to_string(side);
    const double gap = smallestGap(layout, curve.points, layout.pointsOn(target, stations, net.warnings), stations);
    if (gap < settings.net.minGap)
      net.warnings.push_back(curve.label + " comes within " + std::to_string(gap) + " mm of " + target.label +
                             ", less than the minimum gap: the area between them is narrower than the tool there");
    halves[side - 1] = std::move(curve);
    built[side - 1] = true;
  }
  // Each guide was measured for two pairs, and the median inflects next to the boundaries: one per minStep.
  auto& inflections = report.inflectionStations;
  std::sort(inflections.begin(), inflections.end());
  inflections.erase(std::unique(inflections.begin(), inflections.end(),
                                [&](double a, double b) { return b - a < settings.minStep; }),
                    inflections.end());

  net.stations = layout.stations();
  net.direction = layout.frame().direction;
  net.curves.push_back(b1);
  if (built[0]) net.curves.push_back(halves[0]);
  net.curves.push_back(median);
  if (built[1]) net.curves.push_back(halves[1]);
  net.curves.push_back(b2);
  return result;
}

}  // namespace hsm::curvenet
