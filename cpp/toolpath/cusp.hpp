// The cusp left between two neighbouring passes of a ball-end tool on one face, measured on the geometry.
//
// In the plane normal to the path of the first ball's centre, that ball cuts a circle of the tool radius;
// the next pass cuts the union of its balls' sections. The ridge between the passes is where the circle
// enters that union on the face's side, and the cusp is the ridge's height above the face. A disc of the
// next pass's ball nearest the plane gives an upper bound at once; only where that bound exceeds the cusp
// height are the next pass's balls sampled finely around it. This holds where a station's contact slides
// along the pass from one pass to the next (passes crossing valleys at a slant, morphed passes), where a
// spacing of contact points would crowd the passes, and where the next pass bends out of the plane.
#pragma once

#include "toolpath/surface_drop.hpp"

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <vector>

namespace hsm::toolpath {

// Where the ball above a plan position touches the face, and its centre.
struct BallContact {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  double u = 0.0, v = 0.0;
  bool inside = false;  // the contact is on the face
  Eigen::Vector3d centre = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  bool dropped() const { return centre.x() == centre.x(); }
};

class CuspGauge {
public:
  CuspGauge(const SurfaceBallDrop& ball, double toolRadius);

  // The contacts of the ball above plan positions along a pass (not dropped where Newton finds none).
  std::vector<BallContact> contacts(const std::vector<Eigen::Vector2d>& plan) const;

  // The cusp between the pass `here` at station k and the next pass (its plan positions and contacts at the
  // same stations); empty where it cannot be told (no neighbour to give the path's direction, the ridge's
  // foot off the face). Infinite when the passes are a tool diameter or more apart.
  std::optional<double> cusp(const std::vector<BallContact>& here, size_t k, const std::vector<Eigen::Vector2d>& nextPlan,
                             const std::vector<BallContact>& next, double cuspHeight) const;

private:
  std::optional<double> heightAboveFace(const Eigen::Vector3d& q, double u, double v, const Eigen::Vector3d& up) const;
  std::optional<Eigen::Vector3d> centreAt(const Eigen::Vector2d& plan, SurfaceBallDrop::Result& state) const;

  const SurfaceBallDrop& ball_;
  double radius_;
  double u0_ = 0.0, u1_ = 0.0, v0_ = 0.0, v1_ = 0.0;  // the surface's parameter bounds
};

}  // namespace hsm::toolpath
