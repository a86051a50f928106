// The meridian of a surface of revolution (internal to the roughing): a polyline in the half-plane (ρ, z) about
// the axis, and the coordinates it gives that half-plane — along the meridian (arc length s) and across it
// (signed distance d, positive on the volume's side). Offsets of the surface are the curves d = constant; their
// normal lines, s = constant, are straight and shared by every offset: they are the tool axes of S4 and S5.
//
// Between two vertices the normal is interpolated linearly (not normalised), so that the normal lines sweep
// the plane without a gap or a jump: a point lies on the normal line of s where (q − M(s)) × N(s) = 0, a
// quadratic on each segment. Both ends are extended along their tangents (straight, one normal), so that the
// whole part and stock have coordinates.
#pragma once

#include <Eigen/Core>
#include <TopoDS_Face.hxx>

#include <optional>
#include <vector>

namespace hsm::roughing {

// Samples of a meridian: the partition's slicing surfaces and the sweep's passes are built on the same ones.
inline constexpr int kMeridianSamples = 81;

class Meridian {
public:
  // `samples` points of the face's meridian (its surface along v at the face's middle u, over the surface's v
  // range where it is bounded, else the face's), the volume on the side of the face's inward normal, the ends
  // extended by `extension` mm (stopping short of the axis).
  Meridian(const TopoDS_Face& face, const Eigen::Vector3d& axisPoint, const Eigen::Vector3d& axis, int samples,
           double extension);

  // (ρ, z) of a point of space about the axis.
  Eigen::Vector2d plane(const Eigen::Vector3d& p) const;
  // The sampled meridian (without its extensions) and its unit normals towards the volume at the samples.
  const std::vector<Eigen::Vector2d>& samples() const { return samples_; }
  Eigen::Vector2d sampleNormal(size_t i) const;
  // Unsigned distance from q to the sampled polyline (ends clamped).
  double distance(const Eigen::Vector2d& q) const;

  struct Place {
    double s = 0.0, d = 0.0;  // mm along the (extended) meridian, from its extended start; mm across it
  };
  // The normal line q lies on, and how far along it; none when q is on no normal line within the extensions
  // (beyond the axis-side end, say). The nearest such line when several meet q (past the centres of curvature).
  std::optional<Place> locate(const Eigen::Vector2d& q) const;
  Eigen::Vector2d at(double s, double d) const;          // the point of (s, d)
  Eigen::Vector2d normal(double s) const;                // unit, towards the volume
  // How much longer a step along the offset at d is than the same step of s (1 on the meridian): the
  // meridional scale of the (s, d) coordinates.
  double stretch(double s, double d) const;
  double length() const { return arc_.back(); }
  const Eigen::Vector3d& axisPoint() const { return axisPoint_; }
  const Eigen::Vector3d& axis() const { return axis_; }

private:
  size_t segmentOf(double s) const;
  Eigen::Vector3d axisPoint_, axis_;
  std::vector<Eigen::Vector2d> samples_;
  std::vector<Eigen::Vector2d> vertices_, normals_;  // extended polyline and its (unit) vertex normals
  std::vector<double> arc_;                          // arc length at each vertex
  double sign_ = 1.0;
};

}  // namespace hsm::roughing
