#include "toolpath/finishing.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/plane_cutter.hpp"
#include "toolpath/linking.hpp"
#include "toolpath/passes.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hsm::toolpath {

using namespace detail;

void checkFinishingSettings(const FinishingSettings& settings) { validate(settings); }

Toolpath parallelPlaneFinishing(const TopoDS_Shape& part, int bottomFace, double angleDeg,
                                const FinishingSettings& settings) {
  if (!std::isfinite(angleDeg)) throw InputError("the angle of the planes must be a number of degrees");
  Context context(part, bottomFace, settings);
  const double a = angleDeg * M_PI / 180.0;
  const Vector2 along(std::cos(a), std::sin(a)), across(-std::sin(a), std::cos(a));
  const Vector2 lo = context.faceMin(), hi = context.faceMax();
  double a0 = kInfinity, a1 = -kInfinity, q0 = kInfinity, q1 = -kInfinity;
  for (const Vector2& corner : {lo, hi, Vector2(lo.x(), hi.y()), Vector2(hi.x(), lo.y())}) {
    a0 = std::min(a0, corner.dot(along));
    a1 = std::max(a1, corner.dot(along));
    q0 = std::min(q0, corner.dot(across));
    q1 = std::max(q1, corner.dot(across));
  }
  const double margin = settings.toolRadius + 1.0;
  context.checkWork(q1 - q0, a1 - a0 + 2.0 * margin);
  Family family;
  family.begin = q0 + 1e-3;
  family.end = q1 - 1e-3;
  family.plan = [=](double q, double spacing) {
    std::vector<Vector2> plan;
    for (double t = a0 - margin; t <= a1 + margin + 1e-9; t += spacing) plan.push_back(t * along + q * across);
    return plan;
  };
  const std::vector<double> parameters = passParameters(context, family, false, {});
  return finish(context, {cutPasses(context, family, parameters, {})}, bottomFace,
                "the walls around it hold the tool up everywhere (a ball finishes a floor only where it fits): use "
                "a smaller ball");
}

namespace {
// Points of the guides in the planes of one spacing: every pass is a blend of the same two point lists.
class GuidePoints {
public:
  GuidePoints(const geometry::PlaneCutter& first, const geometry::PlaneCutter& second, double s0,
              double s1)
      : first_(first), second_(second), s0_(s0), s1_(s1) {}

  const std::pair<geometry::PointArray, geometry::PointArray>& at(double spacing) {
    auto found = cache_.find(spacing);
    if (found != cache_.end()) return found->second;
    std::vector<double> stations;
    for (double s = s0_; s < s1_; s += spacing) stations.push_back(s);
    stations.push_back(s1_);
    return cache_.emplace(spacing, std::make_pair(first_.cut(stations).points, second_.cut(stations).points))
        .first->second;
  }

private:
  const geometry::PlaneCutter &first_, &second_;
  double s0_, s1_;
  std::map<double, std::pair<geometry::PointArray, geometry::PointArray>> cache_;
};
}  // namespace

Toolpath guideCurveFinishing(const TopoDS_Shape& part, int bottomFace, const std::vector<GuideArea>& areas,
                             const Eigen::Vector3d& directionIn, const FinishingSettings& settings) {
  if (areas.empty()) throw InputError("no area to machine: give at least one pair of guide curves");
  if (!directionIn.allFinite() || directionIn.head<2>().norm() < 1e-9)
    throw InputError("the machining direction must be a horizontal vector, e.g. (1, 0, 0)");
  Context context(part, bottomFace, settings);
  const Vector3 direction = Vector3(directionIn.x(), directionIn.y(), 0.0).normalized();
  std::vector<std::vector<std::vector<Pass>>> groups;
  const double extension = (settings.extension >= 0 ? settings.extension : settings.toolRadius) + 1.0;
  for (size_t index = 0; index < areas.size(); ++index) {
    const GuideArea& area = areas[index];
    const std::string name = "area " + std::to_string(index + 1);
    if (area.first.IsNull() || area.second.IsNull()) throw InputError(name + " lacks a guide");
    const geometry::PlaneCutter first(area.first, direction), second(area.second, direction);
    const double s0 = std::max(first.extent().first, second.extent().first);
    const double s1 = std::min(first.extent().second, second.extent().second);
    if (s1 - s0 < settings.sampling)
      throw InputError("the guides of " + name + " do not overlap along the machining direction: pick guides "
                       "on either side of the area");
    GuidePoints guides(first, second, s0, s1);
    const auto& [a, b] = guides.at(std::max(settings.sampling, (s1 - s0) / 200.0));
    const double width = (b - a).leftCols(2).rowwise().norm().maxCoeff();
    if (width < 1e-3)
      throw InputError("the guides of " + name + " coincide (at most " + mm(width) + " apart): pick two different "
                       "curves on either side of the area");
    context.checkWork(width, s1 - s0 + 2.0 * extension);
    Family family;
    family.plan = [&guides, extension](double lambda, double spacing) {
      const auto& [a, b] = guides.at(spacing);
      std::vector<Vector2> plan;
      for (Eigen::Index k = 0; k < a.rows(); ++k) {
        const Eigen::RowVector3d p = a.row(k) + lambda * (b.row(k) - a.row(k));
        plan.emplace_back(p.x(), p.y());
      }
      // Straight on past both ends, so that the pass can leave an open boundary.
      if (plan.size() >= 2) {
        const Vector2 head = (plan[0] - plan[1]).normalized(), tail = (plan.back() - plan[plan.size() - 2]).normalized();
        const Vector2 start = plan.front(), end = plan.back();
        std::vector<Vector2> before, after;
        for (double e = spacing; e <= extension + 1e-9; e += spacing) {
          before.push_back(start + e * head);
          after.push_back(end + e * tail);
        }
        plan.insert(plan.begin(), before.rbegin(), before.rend());
        plan.insert(plan.end(), after.begin(), after.end());
      }
      return plan;
    };
    const Phase phase{double(index) / areas.size(), 1.0 / areas.size()};
    const std::vector<double> parameters = passParameters(context, family, index > 0, phase);
    groups.push_back(cutPasses(context, family, parameters, phase));
  }
  return finish(context, std::move(groups), bottomFace,
                "check that the guides lie on the face, and that the ball fits between its walls");
}

}  // namespace hsm::toolpath
