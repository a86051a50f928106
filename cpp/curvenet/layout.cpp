#include "curvenet/layout.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/bspline.hpp"


#include <cmath>
#include <sstream>

namespace hsm::curvenet::detail {

namespace {
constexpr double kExtentTolerance = 1e-3;  // mm: extents that differ by less are the same
constexpr double kTouchTolerance = 1e-6;   // mm: boundaries closer than this have no side

Eigen::Vector3d chord(const Handle(Geom_BSplineCurve)& curve, const Eigen::Vector3d& axis) {
  const gp_Vec v(curve->StartPoint(), curve->EndPoint());
  const Eigen::Vector3d c(v.X(), v.Y(), v.Z());
  return c - axis.dot(c) * axis;
}

// Default machining direction: the mean of the boundaries' chords seen along the tool axis, snapped to a
// machine axis when within kSnapDegrees (die features are modelled along the machine axes; the paper's
// "parallel to the length L140" is X on a part whose boundaries' chords lean by 3°).
constexpr double kSnapDegrees = 10.0;

Eigen::Vector3d lengthDirection(const Boundaries& boundaries, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d c1 = chord(boundaries.b1, axis);
  Eigen::Vector3d c2 = chord(boundaries.b2, axis);
  if (c1.dot(c2) < 0) c2 = -c2;
  const Eigen::Vector3d sum = c1 + c2;
  if (sum.norm() < 1e-6)
    throw InputError("the boundaries have no length direction (closed or vertical curves): give the machining "
                     "direction");
  Eigen::Vector3d direction = sum.normalized();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d machineAxis = Eigen::Vector3d::Unit(i);
    const Eigen::Vector3d inPlane = machineAxis - axis.dot(machineAxis) * axis;
    if (inPlane.norm() < 0.5) continue;
    const double cosine = direction.dot(inPlane.normalized());
    if (std::abs(cosine) >= std::cos(kSnapDegrees * M_PI / 180.0)) {
      direction = inPlane.normalized();
      break;
    }
  }
  int largest = 0;
  direction.cwiseAbs().maxCoeff(&largest);
  return direction[largest] < 0 ? Eigen::Vector3d(-direction) : direction;  // +X for a feature along X
}

void requireBSpline(const Handle(Geom_BSplineCurve)& curve, const char* name) {
  if (curve.IsNull()) throw InputError(std::string(name) + " is missing: pass an edge, a wire or an (N,3) array");
}
}  // namespace

std::vector<double> evenStations(double from, double to, double step) {
  const double needed = std::ceil((to - from) / step - 1e-9);
  if (!(needed <= kMaxPlanes))
    throw InputError("step P = " + mm(step) + " gives " + number(needed) + " planes over the " + mm(to - from) +
                     " the boundaries share; the limit is " + std::to_string(kMaxPlanes) + " planes: use P of at least " +
                     mm((to - from) / kMaxPlanes) + " (the paper uses 5 mm)");
  const int intervals = std::max(1, static_cast<int>(needed));
  std::vector<double> stations(intervals + 1);
  for (int i = 0; i <= intervals; ++i) stations[i] = from + (to - from) * i / intervals;
  return stations;
}

Layout::Layout(const Boundaries& boundaries, const NetSettings& settings, std::vector<std::string>& warnings,
               std::optional<std::vector<double>> stations)
    : settings_(settings), input_(boundaries) {
  requireBSpline(boundaries.b1, "boundary 1");
  requireBSpline(boundaries.b2, "boundary 2");
  if (!(settings.step >= kMinStep) || !std::isfinite(settings.step))
    throw InputError("step P = " + mm(settings.step) + " must be at least " + mm(kMinStep) + ": the paper uses 5 mm");
  if (!(settings.fitTolerance >= kMinFitTolerance && settings.fitTolerance <= 1.0))
    throw InputError("fit tolerance " + mm(settings.fitTolerance) + " must be in [" + mm(kMinFitTolerance) +
                     ", 1 mm], e.g. 0.01 mm");
  if (!(settings.minGap >= 0.0) || !std::isfinite(settings.minGap))
    throw InputError("minimum gap " + mm(settings.minGap) + " must be 0 or more, e.g. the tool radius 2 mm");
  if (settings.maxCurvesPerNet < 1 || settings.maxCurvesPerNet > 10000)
    throw InputError("the curve limit per net " + std::to_string(settings.maxCurvesPerNet) + " must be 1 to 10000");
  if (!(settings.pinchFraction >= 0.0 && settings.pinchFraction < 1.0))
    throw InputError("pinch fraction " + std::to_string(settings.pinchFraction) + " must be in [0, 1), e.g. 0.25");
  frame_ = makeFrame(warnings);
  b1_ = std::make_unique<PlaneCutter>(boundaries.b1, frame_.direction);
  b2_ = std::make_unique<PlaneCutter>(boundaries.b2, frame_.direction);
  const auto [lo1, hi1] = b1_->extent();
  const auto [lo2, hi2] = b2_->extent();
  from_ = std::max(lo1, lo2);
  to_ = std::min(hi1, hi2);
  if (to_ - from_ <= kExtentTolerance)
    throw InputError("the boundaries do not overlap along the machining direction (B1 spans " + mm(lo1) + ".." +
                     mm(hi1) + ", B2 " + mm(lo2) + ".." + mm(hi2) + "): pick two edges on either side of the "
                     "bottom, or give the machining direction");
  if (from_ - std::min(lo1, lo2) > kExtentTolerance || std::max(hi1, hi2) - to_ > kExtentTolerance)
    warnings.push_back("the boundaries have different extents along the machining direction (B1 " + mm(lo1) + ".." +
                       mm(hi1) + ", B2 " + mm(lo2) + ".." + mm(hi2) + "): the net covers only " + mm(from_) + ".." +
                       mm(to_));
  if (settings.step > to_ - from_)
    throw InputError("step P = " + mm(settings.step) + " is longer than the common extent of the boundaries (" +
                     mm(to_ - from_) + "): use a step of at most a fifth of it so that the curves keep degree 5");
  placeStations(std::move(stations));
  if (settings.face) dropper_ = std::make_unique<geometry::FaceDropper>(*settings.face, frame_.axis);
  checkBoundaries(warnings);
}

Frame Layout::makeFrame(std::vector<std::string>& warnings) const {
  Frame frame;
  if (!settings_.toolAxis.allFinite() || settings_.toolAxis.norm() < 1e-12)
    throw InputError("tool axis is zero: pass a unit vector, e.g. (0, 0, 1)");
  frame.axis = settings_.toolAxis.normalized();
  Eigen::Vector3d direction;
  if (settings_.direction) {
    direction = *settings_.direction;
    if (!direction.allFinite() || direction.norm() < 1e-12)
      throw InputError("machining direction is zero: pass a vector along the feature, e.g. (1, 0, 0)");
    direction.normalize();
    const Eigen::Vector3d planar = direction - frame.axis.dot(direction) * frame.axis;
    if (planar.norm() < 1e-6)
      throw InputError("machining direction is along the tool axis: the planes must contain the tool axis; "
                       "pass a direction across it, e.g. (1, 0, 0)");
    if (planar.norm() < std::cos(M_PI / 180.0))
      warnings.push_back("machining direction tilted from the plane normal to the tool axis: its projection on "
                         "that plane is used");
    direction = planar.normalized();
  } else {
    direction = lengthDirection(input_, frame.axis);
  }
  frame.direction = direction;
  frame.transverse = frame.axis.cross(direction).normalized();
  return frame;
}

void Layout::placeStations(std::optional<std::vector<double>> stations) {
  if (!stations) {
    stations_ = evenStations(from_, to_, settings_.step);
    return;
  }
  stations_ = std::move(*stations);
  for (size_t i = 0; i < stations_.size(); ++i) {
    if (stations_[i] < from_ - kExtentTolerance || stations_[i] > to_ + kExtentTolerance ||
        (i > 0 && stations_[i] <= stations_[i - 1]))
      throw InputError("planes must be increasing and inside the common extent " + mm(from_) + ".." + mm(to_));
    stations_[i] = std::clamp(stations_[i], from_, to_);
  }
}

void Layout::checkBoundaries(std::vector<std::string>& warnings) {
  const auto cuts1 = b1_->cut(stations_);
  const auto cuts2 = b2_->cut(stations_);
  b1Points_ = cuts1.points;
  b2Points_ = cuts2.points;
  putBoundariesOnFace(warnings);
  for (const auto& [cuts, name] : {std::pair{&cuts1, "B1"}, std::pair{&cuts2, "B2"}})
    if (!cuts->multiCutStations.empty())
      warnings.push_back(std::to_string(cuts->multiCutStations.size()) + " plane(s) cut " + name +
                         " more than once (first at " + mm(stations_[cuts->multiCutStations.front()]) +
                         "): the cut that continues the curve was used");
  contact_.assign(stations_.size(), 0);
  const double widest = (b2Points_ - b1Points_).rowwise().norm().maxCoeff();
  if (settings_.minGap >= widest && widest > kTouchTolerance)
    throw InputError("minimum gap " + mm(settings_.minGap) + " is as wide as the area (the boundaries are at most " +
                     mm(widest) + " apart): no curve could be built; use a gap well below that, e.g. the tool "
                     "radius (2 mm)");
  widest_ = widest;
  const double pinch = std::max(settings_.minGap, settings_.pinchFraction * widest);
  int side = 0;
  for (size_t i = 0; i < stations_.size(); ++i) {
    const Eigen::Vector3d across = (b2Points_.row(i) - b1Points_.row(i)).transpose();
    contact_[i] = across.norm() < pinch;
    if (across.norm() < kTouchTolerance) continue;
    const int here = frame_.transverse.dot(across) > 0 ? 1 : -1;
    if (side != 0 && here != side)
      throw InputError("the boundaries cross near " + mm(stations_[i]) + " along the machining direction: the "
                       "region between them is not one area; split the edges at the crossing and build one net "
                       "on each side");
    side = here;
  }
  if (side == 0) throw InputError("the boundaries coincide: pick two different edges");
  if (side < 0) frame_.transverse = -frame_.transverse;  // B1 on the low side of the transverse direction
  const long touching = std::count(contact_.begin(), contact_.end(), 1);
  if (touching > 0)
    warnings.push_back(std::to_string(touching) + " plane(s) where the boundaries pinch (closer than " + mm(pinch) +
                       "): the stop rule ignores them and the curves crowd there");
}

// Boundaries drawn off the face (a sketch above it) have their points put on it, so that distances to them
// are measured on the face; the curves built from them do not change (their points are put on the face
// along the axis anyway).
void Layout::putBoundariesOnFace(std::vector<std::string>& warnings) {
  if (!dropper_) return;
  for (auto [points, name] : {std::pair{&b1Points_, "B1"}, std::pair{&b2Points_, "B2"}}) {
    const PointArray drawn = *points;
    dropper_->drop(*points);
    const double off = (*points - drawn).rowwise().norm().maxCoeff();
    if (off <= 0.01) {
      *points = drawn;  // on the face already: its own points, not their drops (which differ by 1e-10)
      continue;
    }
    warnings.push_back(std::string(name) + " lies up to " + mm(off) + " off the bottom face along the tool axis: "
                       "its points were put on the face (pick the face's own edges to avoid this)");
  }
}

PointArray Layout::pointsOn(const NetCurve& curve, const std::vector<double>& stations,
                            std::vector<std::string>& warnings) const {
  const bool layoutPlanes = &stations == &stations_ || stations == stations_;
  if (curve.role == CurveRole::Boundary) {
    const bool first = curve.label == "B1";
    if (layoutPlanes) return first ? b1Points_ : b2Points_;
    return (first ? b1_ : b2_)->cut(stations).points;
  }
  if (layoutPlanes && curve.points.rows() == static_cast<Eigen::Index>(stations.size())) return curve.points;
  const auto cuts = PlaneCutter(curve.curve, frame_.direction).cut(stations);
  if (!cuts.multiCutStations.empty())
    warnings.push_back(std::to_string(cuts.multiCutStations.size()) + " plane(s) cut " + curve.label +
                       " more than once: the cut that continues the curve was used");
  return cuts.points;
}

void Layout::dropOnFace(PointArray& points, std::vector<std::string>& warnings) const {
  if (!dropper_) return;
  long failed = 0, outside = 0;
  bool haveGuess = false;
  double u = 0.0, v = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const bool dropped = dropper_->dropOne(points.row(i), u, v, haveGuess);
    haveGuess = haveGuess || dropped;
    if (!dropped) ++failed;
    // The end planes meet the face's own edges, where inside or not cannot be told: only the others count.
    else if (i > 0 && i + 1 < points.rows() && !dropper_->inside(u, v)) ++outside;
  }
  if (failed > 0)
    warnings.push_back(std::to_string(failed) + " point(s) could not be put on the bottom face along the tool axis "
                       "(the face is vertical or absent there): they stay between the curves");
  if (outside > 0)
    warnings.push_back(std::to_string(outside) + " point(s) of a curve lie over a hole or past the edge of the "
                       "bottom face: the curve crosses it there (the finishing bridges holes at the face's level)");
}

bool Layout::tooClose(const PointArray& start, const PointArray& candidate, const PointArray& target) const {
  for (Eigen::Index i = 0; i < candidate.rows(); ++i) {
    if (contact_[static_cast<size_t>(i)]) continue;
    const Eigen::Vector3d toTarget = (target.row(i) - candidate.row(i)).transpose();
    if (toTarget.norm() < settings_.minGap) return true;
    const Eigen::Vector3d fromStart = (target.row(i) - start.row(i)).transpose();
    if (frame_.transverse.dot(toTarget) * frame_.transverse.dot(fromStart) < 0) return true;
  }
  return false;
}

}  // namespace hsm::curvenet::detail
