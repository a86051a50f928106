#include "curvenet/curvenet.hpp"
#include "curvenet/layout.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace hsm::curvenet {

using detail::boundaryCurve;
using detail::buildCurve;
using detail::checkRatio;
using detail::Layout;

namespace detail {

void checkRatio(double k, const char* name) {
  if (!(k > 0.0 && k < 1.0)) {
    std::ostringstream message;
    message << name << " = " << k << " is outside ]0,1[: K = 0 gives the starting curve and K = 1 the target; "
            << "use a value strictly between, e.g. 0.5 for the median or 0.75 near the target";
    throw InputError(message.str());
  }
}

NetCurve boundaryCurve(const Layout& layout, int which) {
  NetCurve curve;
  curve.role = CurveRole::Boundary;
  curve.label = which == 1 ? "B1" : "B2";
  curve.curve = layout.boundary(which).curve();
  return curve;
}

// Points of `start` and `target` in the layout's planes, then eq. 2: P = Pa + K·(Pb − Pa).
NetCurve buildCurve(const Layout& layout, const NetCurve& start, const NetCurve& target, double k,
                    const std::vector<double>& stations, std::vector<std::string>& warnings) {
  const PointArray a = layout.pointsOn(start, stations, warnings);
  const PointArray b = layout.pointsOn(target, stations, warnings);
  NetCurve curve;
  curve.k = k;
  curve.from = start.label;
  curve.towards = target.label;
  curve.points = a + k * (b - a);
  layout.dropOnFace(curve.points, warnings);
  auto [spline, deviation] = detail::fitCurve(curve.points, layout.settings().fitTolerance);
  curve.curve = spline;
  curve.fitDeviation = deviation;
  if (curve.points.rows() < 6)
    warnings.push_back("only " + std::to_string(curve.points.rows()) + " planes between " + start.label + " and " +
                       target.label + ": the curve has degree " + std::to_string(spline->Degree()) +
                       " instead of 5; use a smaller step P");
  return curve;
}

}  // namespace detail

namespace {

// Refuses a K with which a net would need more curves than the limit: each curve closes the share K of
// the gap left to its target, so from a width W about log(gap/W)/log(1 − K) curves end it.
void checkCurveCount(const Layout& layout, double k, double width) {
  const double gap = std::max(layout.settings().minGap, 1e-3);
  if (width <= gap) return;
  const double curves = std::log(gap / width) / std::log(1.0 - k);
  const int limit = layout.settings().maxCurvesPerNet;
  if (curves > limit) {
    const double kMin = 1.0 - std::pow(gap / width, 1.0 / limit);
    throw InputError("K = " + number(k) + " would build about " + number(std::ceil(curves)) + " curves across " +
                     mm(width) + " (each closes " + number(100.0 * k) + " % of the gap left) and the limit is " +
                     std::to_string(limit) + ": use K of at least " + number(std::ceil(kMin * 1000.0) / 1000.0) +
                     " or a larger minimum gap");
  }
}

// Grows a net from `start` towards `target` until the stop rule drops a curve (see curvenet.hpp).
std::vector<NetCurve> growNet(const Layout& layout, const NetCurve& start, const NetCurve& target, double k,
                              int net, std::vector<std::string>& warnings, const std::function<void(double)>& progress) {
  std::vector<NetCurve> built;
  const std::vector<double>& stations = layout.stations();
  const PointArray targetPoints = layout.pointsOn(target, stations, warnings);
  const NetCurve* current = &start;
  for (int rank = 1;; ++rank) {
    if (rank > layout.settings().maxCurvesPerNet)
      throw ComputationError("the net from " + start.label + " reached " +
                             std::to_string(layout.settings().maxCurvesPerNet) + " curves without coming within the "
                             "minimum gap of " + target.label + ": use a larger K or minimum gap");
    progress(double(rank));
    NetCurve candidate = buildCurve(layout, *current, target, k, stations, warnings);
    const PointArray startPoints = layout.pointsOn(*current, stations, warnings);
    if (layout.tooClose(startPoints, candidate.points, targetPoints)) break;
    candidate.net = net;
    candidate.rank = rank;
    candidate.label = "C" + std::to_string(net) + "." + std::to_string(rank);
    built.push_back(std::move(candidate));
    current = &built.back();
  }
  return built;
}

NetCurve medianCurve(const Layout& layout, double k, std::vector<std::string>& warnings) {
  NetCurve median = buildCurve(layout, boundaryCurve(layout, 1), boundaryCurve(layout, 2), k, layout.stations(),
                               warnings);
  median.role = CurveRole::Median;
  median.label = "Cmed";
  return median;
}

template <class It>
void append(std::vector<NetCurve>& to, It first, It last) {
  to.insert(to.end(), first, last);
}

}  // namespace

std::string netModeName(NetMode mode) {
  switch (mode) {
    case NetMode::B1ToB2: return "b1_to_b2";
    case NetMode::B2ToB1: return "b2_to_b1";
    case NetMode::Median: return "median";
    case NetMode::MedianToBoundaries: return "median_to_boundaries";
    case NetMode::BoundariesToMedian: return "boundaries_to_median";
  }
  return "?";
}

NetCurve intermediateCurve(const Handle(Geom_BSplineCurve)& ca, const Handle(Geom_BSplineCurve)& cb, double k,
                           const NetSettings& settings) {
  checkRatio(k, "K");
  std::vector<std::string> warnings;
  const Layout layout({ca, cb}, settings, warnings);
  NetCurve curve = buildCurve(layout, boundaryCurve(layout, 1), boundaryCurve(layout, 2), k, layout.stations(),
                              warnings);
  curve.label = "C";
  curve.from = "Ca";
  curve.towards = "Cb";
  return curve;
}

CurveNet curveNet(const Boundaries& boundaries, double k, NetMode mode, const NetSettings& settings) {
  if (mode != NetMode::Median) checkRatio(k, "K");
  if (mode != NetMode::Median && !(settings.minGap > 0.0))
    throw InputError("minimum gap " + mm(settings.minGap) + " must be positive: with no gap a net halves the "
                     "distance to its target for ever; use the tool radius, e.g. 2 mm");
  CurveNet net;
  const Layout layout(boundaries, settings, net.warnings);
  net.stations = layout.stations();
  net.direction = layout.frame().direction;
  const NetCurve b1 = boundaryCurve(layout, 1), b2 = boundaryCurve(layout, 2);
  const bool halves = mode == NetMode::MedianToBoundaries || mode == NetMode::BoundariesToMedian;
  const double width = layout.widest() * (halves ? 0.5 : 1.0);
  if (mode != NetMode::Median) checkCurveCount(layout, k, width);
  // Progress per curve built, against the count the stop rule should reach.
  const double gap = std::max(settings.minGap, 1e-3);
  const double perNet = width > gap && mode != NetMode::Median ? std::log(gap / width) / std::log(1.0 - k) : 1.0;
  const double expected = std::max(1.0, (halves ? 2.0 : 1.0) * perNet);
  ProgressReporter reporter(settings.progress, "curve net");
  int built = 0;
  const std::function<void(double)> progress = [&](double) { reporter(std::min(1.0, ++built / expected)); };
  auto& curves = net.curves;
  curves.push_back(b1);
  switch (mode) {
    case NetMode::B1ToB2: {
      const auto grown = growNet(layout, b1, b2, k, 1, net.warnings, progress);
      append(curves, grown.begin(), grown.end());
      break;
    }
    case NetMode::B2ToB1: {
      const auto grown = growNet(layout, b2, b1, k, 2, net.warnings, progress);
      append(curves, grown.rbegin(), grown.rend());
      break;
    }
    case NetMode::Median:
      curves.push_back(medianCurve(layout, 0.5, net.warnings));
      break;
    case NetMode::MedianToBoundaries: {
      const NetCurve median = medianCurve(layout, 0.5, net.warnings);
      const auto half1 = growNet(layout, median, b1, k, 1, net.warnings, progress);
      const auto half2 = growNet(layout, median, b2, k, 2, net.warnings, progress);
      append(curves, half1.rbegin(), half1.rend());
      curves.push_back(median);
      append(curves, half2.begin(), half2.end());
      break;
    }
    case NetMode::BoundariesToMedian: {
      const NetCurve median = medianCurve(layout, 0.5, net.warnings);
      const auto half1 = growNet(layout, b1, median, k, 1, net.warnings, progress);
      const auto half2 = growNet(layout, b2, median, k, 2, net.warnings, progress);
      append(curves, half1.begin(), half1.end());
      curves.push_back(median);
      append(curves, half2.rbegin(), half2.rend());
      break;
    }
  }
  curves.push_back(b2);
  reporter(1.0);
  return net;
}

std::vector<ElementaryArea> CurveNet::elementaryAreas() const {
  std::vector<ElementaryArea> areas;
  for (int i = 0; i + 1 < static_cast<int>(curves.size()); ++i) areas.push_back({i, i + 1});
  return areas;
}

std::vector<std::vector<ElementaryArea>> CurveNet::composedAreas() const {
  int maxRank = 0;
  bool hasMedian = false;
  for (const NetCurve& c : curves) {
    maxRank = std::max(maxRank, c.rank);
    hasMedian = hasMedian || c.role == CurveRole::Median;
  }
  // MA_1 holds the boundaries (and the median); each next MA adds the next curve built by each net.
  std::vector<std::vector<ElementaryArea>> composed;
  const int first = hasMedian ? 0 : 1;
  for (int rank = first; rank <= std::max(maxRank, first); ++rank) {
    std::vector<int> kept;
    for (int i = 0; i < static_cast<int>(curves.size()); ++i)
      if (curves[i].role != CurveRole::Intermediate || curves[i].rank <= rank) kept.push_back(i);
    std::vector<ElementaryArea> areas;
    for (size_t j = 0; j + 1 < kept.size(); ++j) areas.push_back({kept[j], kept[j + 1]});
    if (composed.empty() || composed.back().size() != areas.size()) composed.push_back(std::move(areas));
  }
  return composed;
}

}  // namespace hsm::curvenet
