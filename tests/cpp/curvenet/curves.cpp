#include "curves.hpp"

#include "curvenet/fitting.hpp"

namespace hsm::test {
double yAt(const Handle(Geom_BSplineCurve)& curve, double x) {
  return curvenet::detail::PlaneCutter(curve, Eigen::Vector3d::UnitX()).cut({x}).points(0, 1);
}
}  // namespace hsm::test
