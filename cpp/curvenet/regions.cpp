#include "curvenet/regions.hpp"
#include "geometry/bounds.hpp"

#include "common/error.hpp"
#include "common/text.hpp"
#include "geometry/bspline.hpp"
#include "geometry/face_drop.hpp"
#include "curvenet/fitting.hpp"

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <GeomLib.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <optional>

namespace hsm::curvenet {

namespace {

// The curve swept along the axis from −height to +height, extended by `margin` past both ends so that
// it cuts the face right across even where the curve ends on the face's own edge.
TopoDS_Shape curtain(const Handle(Geom_BSplineCurve)& curve, const gp_Vec& axis, double height, double margin) {
  Handle(Geom_BoundedCurve) extended = Handle(Geom_BoundedCurve)::DownCast(curve->Copy());
  const double t0 = curve->FirstParameter(), t1 = curve->LastParameter();
  gp_Pnt p;
  gp_Vec tangent;
  curve->D1(t1, p, tangent);
  GeomLib::ExtendCurveToPoint(extended, p.Translated(tangent.Normalized() * margin), 1, Standard_True);
  curve->D1(t0, p, tangent);
  GeomLib::ExtendCurveToPoint(extended, p.Translated(tangent.Normalized() * -margin), 1, Standard_False);
  gp_Trsf down;
  down.SetTranslation(axis * -height);
  const TopoDS_Shape edge = BRepBuilderAPI_Transform(BRepBuilderAPI_MakeEdge(extended).Edge(), down).Shape();
  return BRepPrimAPI_MakePrism(edge, axis * (2.0 * height)).Shape();
}

std::optional<gp_Pnt> interiorPoint(const TopoDS_Face& face) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  BRepTopAdaptor_FClass2d classifier(face, 1e-7);
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  for (int n : {3, 7, 15, 31}) {
    for (int i = 1; i < n; ++i)
      for (int j = 1; j < n; ++j) {
        const gp_Pnt2d uv(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n);
        if (classifier.Perform(uv) == TopAbs_IN) return surface->Value(uv.X(), uv.Y());
      }
  }
  return std::nullopt;
}

// Index of the elementary area whose two curves enclose `point` across the feature.
int enclosingArea(const CurveNet& net, const std::vector<detail::PlaneCutter>& cutters,
                  const Eigen::Vector3d& transverse, const gp_Pnt& point) {
  const Eigen::Vector3d p(point.X(), point.Y(), point.Z());
  const double s = std::clamp(net.direction.dot(p), net.stations.front(), net.stations.back());
  std::vector<double> across;
  for (const auto& cutter : cutters) {
    const auto [lo, hi] = cutter.extent();
    across.push_back(transverse.dot(cutter.cut({std::clamp(s, lo, hi)}).points.row(0).transpose()));
  }
  const double sign = across.back() >= across.front() ? 1.0 : -1.0;  // B1 low, B2 high
  const double here = sign * transverse.dot(p);
  int area = 0;
  for (size_t i = 1; i + 1 < across.size(); ++i)
    if (here > sign * across[i]) area = static_cast<int>(i);
  return area;
}

// Refuses a face the net does not lie on: the net's inner curves (or its boundaries when it has none) are
// sampled and put on the face along the axis; they must land inside it, within a tolerance of the curve.
void checkNetOnFace(const CurveNet& net, const TopoDS_Face& face, const Eigen::Vector3d& axis, double size) {
  const geometry::FaceDropper dropper(face, axis.normalized());
  const bool inner = net.curves.size() > 2;
  const double tolerance = 0.5 + 0.01 * size;
  long samples = 0, landed = 0;
  double farthest = 0.0;
  for (size_t i = inner ? 1 : 0; i < (inner ? net.curves.size() - 1 : net.curves.size()); ++i) {
    PointArray points = geometry::sampleByArcLength(Handle(Geom_Curve)(net.curves[i].curve), 21);
    const PointArray drawn = points;
    const std::vector<char> inside = dropper.dropAndClassify(points);
    for (Eigen::Index k = 1; k + 1 < points.rows(); ++k) {  // the ends may lie on the face's edges
      ++samples;
      if (!inside[static_cast<size_t>(k)]) continue;
      ++landed;
      farthest = std::max(farthest, (points.row(k) - drawn.row(k)).norm());
    }
  }
  if (landed < samples / 2)
    throw InputError("the net does not lie on this face: " + std::to_string(samples - landed) + " of " +
                     std::to_string(samples) + " points of its curves are outside it seen along the tool axis; pass "
                     "the bottom face the net was built on");
  if (farthest > tolerance)
    throw InputError("the net does not lie on this face: its curves are up to " + mm(farthest) + " from it along the "
                     "tool axis (tolerance " + mm(tolerance) + "); pass the bottom face the net was built on");
}

}  // namespace

std::vector<AreaRegion> areaRegions(const CurveNet& net, const TopoDS_Face& face, const Eigen::Vector3d& toolAxis) {
  if (face.IsNull()) throw InputError("the bottom face is null: pass the face the net lies on");
  if (net.curves.size() < 2) throw InputError("the net has fewer than two curves");
  const Bnd_Box box = geometry::exactBounds(face);
  const double size = std::sqrt(box.SquareExtent());
  const gp_Vec axis(toolAxis.x(), toolAxis.y(), toolAxis.z());
  checkNetOnFace(net, face, toolAxis, size);

  try {
    BRepAlgoAPI_Splitter splitter;
    TopTools_ListOfShape arguments, tools;
    arguments.Append(face);
    for (size_t i = 1; i + 1 < net.curves.size(); ++i)
      tools.Append(curtain(net.curves[i].curve, axis.Normalized(), size, 0.05 * size));
    splitter.SetArguments(arguments);
    splitter.SetTools(tools);
    splitter.Build();
    if (splitter.HasErrors()) throw ComputationError("OCCT could not split the bottom face by the net's curves");

    std::vector<detail::PlaneCutter> cutters;
    for (const NetCurve& curve : net.curves) cutters.emplace_back(curve.curve, net.direction);
    const Eigen::Vector3d transverse = toolAxis.normalized().cross(net.direction).normalized();

    std::vector<AreaRegion> regions;
    BRep_Builder builder;
    for (const ElementaryArea& area : net.elementaryAreas()) {
      AreaRegion region;
      region.area = area;
      TopoDS_Compound compound;
      builder.MakeCompound(compound);
      region.faces = compound;
      regions.push_back(region);
    }
    for (TopExp_Explorer it(splitter.Shape(), TopAbs_FACE); it.More(); it.Next()) {
      const TopoDS_Face piece = TopoDS::Face(it.Current());
      const auto point = interiorPoint(piece);
      if (!point) continue;  // a sliver too thin to hold a sample point
      AreaRegion& region = regions[enclosingArea(net, cutters, transverse, *point)];
      builder.Add(region.faces, piece);
      GProp_GProps props;
      BRepGProp::SurfaceProperties(piece, props);
      region.surfaceArea += props.Mass();
    }
    return regions;
  } catch (const Standard_Failure& failure) {
    throw ComputationError(std::string("OCCT failed while splitting the bottom face: ") + failure.GetMessageString());
  }
}

}  // namespace hsm::curvenet
