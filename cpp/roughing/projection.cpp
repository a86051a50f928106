#include "roughing/projection.hpp"
#include "geometry/bounds.hpp"

#include "common/error.hpp"
#include "roughing/meridian.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hsm::roughing {

namespace {

// Two straight lines at an angle θ that meet L away: a point at distance D = L·sin θ from one, on the other,
// is L·θ away measured along the arc; x / asin x (x = D / L) is the scale that holds out to D.
double chordFactor(double x) {
  x = std::min(0.99, x);
  return x > 1e-9 ? x / std::asin(x) : 1.0;
}

cl::IntPoint toInt(double x, double y) {
  return {static_cast<cl::cInt>(std::llround(x * kScale)), static_cast<cl::cInt>(std::llround(y * kScale))};
}

class PlaneProjection : public Projection {
public:
  explicit PlaneProjection(const Eigen::Vector3d& axis) : a_(axis.normalized()) {
    u_ = a_.unitOrthogonal();
    v_ = a_.cross(u_);
  }
  double height(const Eigen::Vector3d& p) const override { return a_.dot(p); }
  cl::IntPoint plane(const Eigen::Vector3d& p) const override { return toInt(u_.dot(p), v_.dot(p)); }
  Eigen::Vector3d point(const cl::IntPoint& q, double h) const override {
    return u_ * (static_cast<double>(q.X) / kScale) + v_ * (static_cast<double>(q.Y) / kScale) + a_ * h;
  }
  Eigen::Vector3d axisAt(const Eigen::Vector3d&) const override { return a_; }
  bool cullsBackFaces() const override { return true; }

private:
  Eigen::Vector3d a_, u_, v_;
};

// Angles about an axis measured from `middle` (a radial direction through the volume: the volume does not
// reach the seam half a turn away).
class Angles {
public:
  Angles(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Eigen::Vector3d& middle)
      : o_(origin), z_(direction.normalized()) {
    e1_ = (middle - z_ * z_.dot(middle)).normalized();
    e2_ = z_.cross(e1_);
  }
  Eigen::Vector3d radial(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d w = p - o_;
    return w - z_ * z_.dot(w);
  }
  double angle(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d w = radial(p);
    return std::atan2(e2_.dot(w), e1_.dot(w));
  }
  Eigen::Vector3d direction(double theta) const { return e1_ * std::cos(theta) + e2_ * std::sin(theta); }
  double along(const Eigen::Vector3d& p) const { return z_.dot(p - o_); }
  const Eigen::Vector3d& origin() const { return o_; }
  const Eigen::Vector3d& axis() const { return z_; }
  // The angles a triangle spans: across the seam (half a turn) it would wrap round and is left out (a volume
  // spanning more than about 340° is not swept with these).
  double span(const Eigen::Vector3d (&p)[3]) const {
    double low = 1e300, high = -1e300;
    for (const Eigen::Vector3d& q : p) low = std::min(low, angle(q)), high = std::max(high, angle(q));
    return high - low;
  }

private:
  Eigen::Vector3d o_, z_, e1_, e2_;
};

// Beyond 2° a straight edge bows when unrolled (r·Δθ²/8: 0.006 mm at r 40).
constexpr double kBendSpan = 2.0 * M_PI / 180.0;

class CylinderProjection : public Projection {
public:
  explicit CylinderProjection(const Angles& angles) : angles_(angles) {}
  void setLevel(double tipHeight, const geometry::TriangleMesh& slice) override {
    r_ = tipHeight;
    largest_ = smallest_ = 1.0;
    for (const Eigen::Vector3d& p : slice.vertices) {
      const double scale = height(p) / r_;
      largest_ = std::max(largest_, scale), smallest_ = std::min(smallest_, scale);
    }
  }
  double height(const Eigen::Vector3d& p) const override { return angles_.radial(p).norm(); }
  cl::IntPoint plane(const Eigen::Vector3d& p) const override { return toInt(r_ * angles_.angle(p), angles_.along(p)); }
  Eigen::Vector3d point(const cl::IntPoint& q, double h) const override {
    const double theta = static_cast<double>(q.X) / kScale / r_;
    return angles_.origin() + angles_.axis() * (static_cast<double>(q.Y) / kScale) + angles_.direction(theta) * h;
  }
  Eigen::Vector3d axisAt(const Eigen::Vector3d& p) const override { return angles_.radial(p).normalized(); }
  double maxSegment(double h, double tolerance) const override {
    // A chord of the circle of radius h dips h·(1 − cos(Δθ/2)) inside it: keep that within the tolerance.
    const double step = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance / std::max(h, tolerance)));
    return r_ * step;
  }
  bool bends(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const override {
    return std::abs(angles_.angle(a) - angles_.angle(b)) > kBendSpan;
  }
  bool skip(const Eigen::Vector3d (&p)[3]) const override { return angles_.span(p) >= M_PI; }
  // Round the axis a flat millimetre at the level's radius is ρ/r true millimetres at radius ρ along the arc;
  // across to a radial tool axis Δθ away the distance is ρ·sin Δθ, shorter: out to the reach, the scale
  // that holds at its end (x / asin x of the reach over ρ).
  Eigen::Vector2d scalesAt(const Eigen::Vector3d& p) const override {
    const double rho = height(p);
    return {rho / r_ * chordFactor(reach_ / std::max(rho, 1e-6)), 1.0};
  }
  double largestScale() const override { return largest_; }
  double smallestScale() const override { return smallest_; }
  // A point at radius ρ, D from a radial tool line round the axis, stands ρ − √(ρ² − D²) ≥ D²/(2ρ) lower
  // along it than its own radius: the level falls away across x by 1/ρ.
  double convexityAt(const Eigen::Vector3d& p) const override { return 1.0 / std::max(height(p), 1e-6); }
  double convexity() const override { return 1.0 / std::max(r_, 1e-6); }

private:
  Angles angles_;
  double r_ = 1.0, largest_ = 1.0, smallest_ = 1.0;
};

class RevolutionProjection : public Projection {
public:
  // `sign`: +1 when the height grows with the distance from the reference surface (S5: the tool stands away
  // from the hub), −1 when it falls (S4: the tool points out through the skin).
  RevolutionProjection(const Angles& angles, std::shared_ptr<const Meridian> meridian, double sign)
      : angles_(angles), meridian_(std::move(meridian)), sign_(sign) {}

  double height(const Eigen::Vector3d& p) const override {
    const auto place = placeOf(p);
    return place ? sign_ * place->d : std::numeric_limits<double>::quiet_NaN();
  }
  cl::IntPoint plane(const Eigen::Vector3d& p) const override {
    const auto place = placeOf(p);
    return toInt(rhoRef_ * angles_.angle(p), place ? place->s : 0.0);
  }
  Eigen::Vector3d point(const cl::IntPoint& q, double h) const override {
    const double theta = static_cast<double>(q.X) / kScale / rhoRef_;
    const Eigen::Vector2d rz = meridian_->at(static_cast<double>(q.Y) / kScale, sign_ * h);
    return angles_.origin() + angles_.axis() * rz.y() + angles_.direction(theta) * rz.x();
  }
  Eigen::Vector3d axisAt(const Eigen::Vector3d& p) const override {
    const auto place = placeOf(p);
    const Eigen::Vector2d n = sign_ * meridian_->normal(place ? place->s : 0.0);
    return (angles_.direction(angles_.angle(p)) * n.x() + angles_.axis() * n.y()).normalized();
  }

  Eigen::Vector3d axisAtPlane(const cl::IntPoint& q, double h) const override {
    (void)h;  // the offsets' normal lines are the reference's: the same axis at every height
    const Eigen::Vector2d n = sign_ * meridian_->normal(static_cast<double>(q.Y) / kScale);
    return (angles_.direction(static_cast<double>(q.X) / kScale / rhoRef_) * n.x() + angles_.axis() * n.y()).normalized();
  }

  void setLevel(double tipHeight, const geometry::TriangleMesh& slice) override {
    // The slice's points carried along their normal lines to the tip's surface: its radii and scales there.
    std::vector<double> s;
    double rhoMax = 0.0;
    rhoMin_ = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : slice.vertices) {
      const auto place = meridian_->locate(meridian_->plane(p));
      if (!place) continue;
      s.push_back(place->s);
      const double rho = meridian_->at(place->s, sign_ * tipHeight).x();
      rhoMax = std::max(rhoMax, rho), rhoMin_ = std::min(rhoMin_, rho);
    }
    if (s.empty() || !(rhoMax > 1e-6))
      throw ComputationError("the offsets of the surface of revolution do not reach the slice: it cannot be laid flat");
    rhoRef_ = rhoMax;
    largest_ = 1.0, smallest_ = 1.0, concavity_ = 0.0, concavityAcross_ = 0.0, meridianCurvature_ = 0.0, convexity_ = 0.0;
    const double dh = 0.05;
    for (double at : s) {
      const double d = sign_ * tipHeight;
      const double rho = meridian_->at(at, d).x(), rhoUp = meridian_->at(at, sign_ * (tipHeight + dh)).x();
      const double stretch = meridian_->stretch(at, d), stretchUp = meridian_->stretch(at, sign_ * (tipHeight + dh));
      largest_ = std::max({largest_, rho / rhoRef_, stretch});
      smallest_ = std::min({smallest_, rho / rhoRef_, stretch});
      // −d ln(scale)/dh: the surface curves up towards the tool where the scales shrink going up.
      const double radial = -(rhoUp - rho) / (dh * rho), meridional = -(stretchUp - stretch) / (dh * stretch);
      concavity_ = std::max({concavity_, radial, meridional});
      concavityAcross_ = std::max(concavityAcross_, radial);
      convexity_ = std::max(convexity_, -radial);
      meridianCurvature_ = std::max(meridianCurvature_, std::abs(meridional));
    }
  }
  double maxSegment(double h, double tolerance) const override {
    (void)h;
    // A chord of length L on a surface of curvature κ leaves it by κ·L²/8; κ ≤ 1/ρ round the axis.
    const double curvature = std::max(1.0 / std::max(rhoMin_, 1e-3), meridianCurvature_);
    return std::sqrt(8.0 * tolerance / curvature) / largest_;
  }
  bool bends(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const override {
    if (std::abs(angles_.angle(a) - angles_.angle(b)) > kBendSpan) return true;
    // The edge's middle lies off the middle of its image's chord by more than 5 µm.
    const cl::IntPoint qa = plane(a), qb = plane(b), qm = plane(0.5 * (a + b));
    return std::hypot(0.5 * double(qa.X + qb.X) - double(qm.X), 0.5 * double(qa.Y + qb.Y) - double(qm.Y)) > 0.005 * kScale;
  }
  bool skip(const Eigen::Vector3d (&p)[3]) const override {
    if (angles_.span(p) >= M_PI) return true;
    for (const Eigen::Vector3d& q : p)
      if (!placeOf(q)) return true;
    return false;
  }
  Eigen::Vector2d scalesAt(const Eigen::Vector3d& p) const override {
    const auto place = placeOf(p);
    if (!place) return {1.0, 1.0};
    // The normal lines converge on the axis round it and on the meridian's centre of curvature along it: over
    // the sweep's reach a point's distance from another line is the sine of their angle, not the angle.
    const double rho = std::max(meridian_->plane(p).x(), 1e-6), h = 1e-2;
    const double stretch = meridian_->stretch(place->s, place->d);
    const double bend = std::abs(meridian_->stretch(place->s, place->d + h) - meridian_->stretch(place->s, place->d - h)) / (2.0 * h);
    // And a point b round the axis and a along the meridian from a tool's line (a² + b² = D²) is
    // a² + b²·(1 − a·t/ρ) squared away where the line stands a·t nearer the axis (t: the meridian's radial
    // share): at worst D²·(1 − 2·D·t/(3√3·ρ)), a scale taken both ways.
    const double t = std::abs(meridian_->normal(place->s).y());
    const double near = std::sqrt(std::max(0.01, 1.0 - 2.0 * reach_ * t / (3.0 * std::sqrt(3.0) * rho)));
    return near * Eigen::Vector2d(rho / rhoRef_ * chordFactor(reach_ / rho),
                                  stretch * chordFactor(reach_ * bend / std::max(stretch, 1e-6)));
  }
  double largestScale() const override { return largest_; }
  double smallestScale() const override { return smallest_; }
  double concavity() const override { return concavity_; }
  double concavityAcross() const override { return concavityAcross_; }
  double convexityAt(const Eigen::Vector3d& p) const override {
    const auto place = placeOf(p);
    if (!place) return 0.0;
    // The tool's lines within the reach along the meridian lean out from the axis by their own radial shares.
    double lean = std::numeric_limits<double>::infinity();
    for (double ds : {-reach_, 0.0, reach_}) lean = std::min(lean, sign_ * meridian_->normal(place->s + ds).x());
    return std::max(0.0, lean) / std::max(meridian_->plane(p).x(), 1e-6);
  }
  double convexity() const override { return convexity_; }

private:
  // The meridian's coordinates of a point, remembered: the sweep asks for the same mesh vertices at every
  // level and several times per triangle (its height, its image, its scale), and locating is the sweep's cost.
  std::optional<Meridian::Place> placeOf(const Eigen::Vector3d& p) const {
    const Key key{p.x(), p.y(), p.z()};
    const auto found = places_.find(key);
    if (found != places_.end()) return found->second;
    if (places_.size() > kMaxRemembered) places_.clear();
    return places_[key] = meridian_->locate(meridian_->plane(p));
  }
  struct Key {
    double x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      const std::hash<double> h;
      return h(k.x) * 0x9E3779B97F4A7C15ull ^ (h(k.y) + 0x632BE59BD9B4E019ull) * 31u ^ h(k.z);
    }
  };
  static constexpr size_t kMaxRemembered = 4000000;
  mutable std::unordered_map<Key, std::optional<Meridian::Place>, KeyHash> places_;
  Angles angles_;
  std::shared_ptr<const Meridian> meridian_;
  double sign_ = 1.0;
  double rhoRef_ = 1.0, rhoMin_ = 1.0, largest_ = 1.0, smallest_ = 1.0, concavity_ = 0.0, concavityAcross_ = 0.0,
         meridianCurvature_ = 0.0, convexity_ = 0.0;
};

Eigen::Vector3d middleOf(const SubVolume& first) {
  Eigen::Vector3d middle = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : first.axisPoints) middle += p - first.surface.origin;
  if (first.axisPoints.empty() || !(middle.norm() > 1e-9))
    throw ComputationError("the sub-volume has no axis field to place its angles on");
  return middle;
}

double sizeOf(const TopoDS_Shape& shape) {
  Bnd_Box box = geometry::exactBounds(shape);
  return std::sqrt(box.SquareExtent());
}

}  // namespace

std::unique_ptr<Projection> projectionOf(const Partition& partition, const RemovalSolid& solid) {
  const SubVolume& first = partition.subVolumes.front();
  const bool fieldKnown = !first.axisDirections.empty();
  if (first.surface.kind == SurfaceKind::Plane) {
    // The tool axis is the planes' normal towards the spindle: out through the reference face, or away from
    // it for S5 (the floor).
    const double away = partition.strategy == Strategy::HubOffsets ? 1.0 : -1.0;
    return std::make_unique<PlaneProjection>(away * first.surface.direction);
  }
  const Angles angles(first.surface.origin, first.surface.direction, middleOf(first));
  if (first.surface.kind == SurfaceKind::Cylinder) {
    // The passes stand on the inner cylinder of each slice, the tool pointing out. (A volume outside the
    // reference cylinder with the tool pointing at the axis, a bore's, is not swept.)
    if (fieldKnown && first.axisDirections.front().dot(angles.radial(first.axisPoints.front())) < 0.0)
      throw InputError("S2 with the volume outside its cylinder (a bore) is not swept: the tool would point at the axis");
    return std::make_unique<CylinderProjection>(angles);
  }
  if (first.surface.kind != SurfaceKind::Revolution)
    throw InputError(strategyName(partition.strategy) + " follows a free-form face (not planar, cylindrical or of "
                     "revolution): its offsets are not swept yet; use S3, or S1/S2 where the volume has their faces");
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid.solid, TopAbs_FACE, faces);
  if (partition.referenceFace < 1 || partition.referenceFace > faces.Extent())
    throw InputError("the partition's reference face " + std::to_string(partition.referenceFace) +
                     " is not a face of this volume: sweep the partition with the volume it was made from");
  auto meridian = std::make_shared<const Meridian>(TopoDS::Face(faces(partition.referenceFace)), first.surface.origin,
                                                   first.surface.direction, kMeridianSamples, sizeOf(solid.solid));
  // The tool stands away from the reference surface for S5 (the hub), out through it for S4 (the skin).
  return std::make_unique<RevolutionProjection>(angles, meridian, partition.strategy == Strategy::HubOffsets ? 1.0 : -1.0);
}

}  // namespace hsm::roughing
