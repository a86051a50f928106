#include "roughing/rays.hpp"
#include "geometry/bounds.hpp"

#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>

namespace hsm::roughing {

RayCaster::RayCaster(const TopoDS_Shape& shape, double tolerance) {
  for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
    faces_.push_back(TopoDS::Face(it.Current()));
    Bnd_Box box = geometry::exactBounds(faces_.back());
    box.Enlarge(tolerance);
    boxes_.push_back(box);
    intersectors_.push_back(std::make_unique<IntCurvesFace_Intersector>(faces_.back(), tolerance));
  }
}

std::vector<RayHit> RayCaster::all(const gp_Lin& line, double from, double to) const {
  std::vector<RayHit> hits;
  for (size_t f = 0; f < faces_.size(); ++f) {
    if (boxes_[f].IsOut(line)) continue;
    IntCurvesFace_Intersector& intersector = *intersectors_[f];
    intersector.Perform(line, from, to);
    if (!intersector.IsDone()) continue;
    for (int i = 1; i <= intersector.NbPnt(); ++i)
      hits.push_back({intersector.WParameter(i), intersector.UParameter(i), intersector.VParameter(i), static_cast<int>(f)});
  }
  std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) { return a.w < b.w; });
  return hits;
}

RayHit RayCaster::nearest(const gp_Lin& line, double from, double to) const {
  const std::vector<RayHit> hits = all(line, from, to);
  return hits.empty() ? RayHit{} : hits.front();
}

}  // namespace hsm::roughing
