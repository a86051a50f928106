#include "roughing/slicing.hpp"
#include "geometry/bounds.hpp"

#include "geometry/mesh.hpp"
#include "roughing/meridian.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomConvert.hxx>
#include <GeomLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Poly_Triangulation.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsm::roughing {

namespace {

Eigen::Vector3d toEigen(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }
gp_Pnt toPoint(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

struct Box {
  Eigen::Vector3d centre;
  double size;  // diagonal
};

Box boxOf(const TopoDS_Shape& shape) {
  Bnd_Box box = geometry::exactBounds(shape);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return {{0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)}, std::hypot(x1 - x0, y1 - y0, z1 - z0)};
}

// The face's normal at the middle of its parameter box, pointing into the solid it bounds.
Eigen::Vector3d inwardNormal(const TopoDS_Face& face, double u, double v) {
  BRepAdaptor_Surface surface(face);
  BRepLProp_SLProps props(surface, u, v, 1, 1e-9);
  gp_Dir n = props.Normal();
  if (face.Orientation() != TopAbs_REVERSED) n.Reverse();  // the face's own normal points out of the solid
  return {n.X(), n.Y(), n.Z()};
}

}  // namespace

Eigen::Vector3d inwardNormalAtCentre(const TopoDS_Face& face, Eigen::Vector3d& point) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
  point = toEigen(BRepAdaptor_Surface(face).Value(u, v).XYZ());
  return inwardNormal(face, u, v);
}

namespace {

class PlaneFamily : public SlicingFamily {
public:
  PlaneFamily(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, const Box& box)
      : origin_(origin), normal_(normal.normalized()), box_(box) {}
  double depth(const gp_Pnt& p) const override { return normal_.dot(toEigen(p.XYZ()) - origin_); }
  TopoDS_Shape surfaceAt(double d) const override {
    const Eigen::Vector3d centre = box_.centre + (d - depth(toPoint(box_.centre))) * normal_;
    const double h = box_.size;
    return BRepBuilderAPI_MakeFace(gp_Pln(toPoint(centre), gp_Dir(normal_.x(), normal_.y(), normal_.z())), -h, h, -h, h).Face();
  }
  SlicingSurface surfaceDescription(double d, int reference) const override {
    SlicingSurface s;
    s.kind = SurfaceKind::Plane;
    s.origin = origin_ + d * normal_;
    s.direction = normal_;
    s.referenceFace = reference;
    s.offset = d;
    return s;
  }

private:
  Eigen::Vector3d origin_, normal_;
  Box box_;
};

class CylinderFamily : public SlicingFamily {
public:
  // Depth grows inwards (towards the axis) when `inward` is true.
  CylinderFamily(const gp_Ax1& axis, double radius, bool inward, const Box& box)
      : point_(toEigen(axis.Location().XYZ())), axis_(toEigen(axis.Direction().XYZ())), radius_(radius),
        sign_(inward ? 1.0 : -1.0), box_(box) {}
  double depth(const gp_Pnt& p) const override { return sign_ * (radius_ - radial(toEigen(p.XYZ())).norm()); }
  TopoDS_Shape surfaceAt(double d) const override {
    const double r = radius_ - sign_ * d;
    if (!(r > 1e-6)) throw InputError("the coaxial cylinders reach the axis: use a larger step or another strategy");
    const double along = axis_.dot(box_.centre - point_);
    const gp_Ax3 frame(toPoint(point_ + (along - box_.size) * axis_), gp_Dir(axis_.x(), axis_.y(), axis_.z()));
    Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(frame, r);
    return BRepBuilderAPI_MakeFace(cylinder, 0.0, 2.0 * M_PI, 0.0, 2.0 * box_.size, 1e-7).Face();
  }
  double crossingCost() const override { return 0.03; }  // 500 coaxial cylinders of the impeller: 90 s
  SlicingSurface surfaceDescription(double d, int reference) const override {
    SlicingSurface s;
    s.kind = SurfaceKind::Cylinder;
    s.origin = point_;
    s.direction = axis_;
    s.radius = radius_ - sign_ * d;
    s.referenceFace = reference;
    s.offset = d;
    return s;
  }

private:
  Eigen::Vector3d radial(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d w = p - point_;
    return w - axis_.dot(w) * axis_;
  }
  Eigen::Vector3d point_, axis_;
  double radius_, sign_;
  Box box_;
};

// Offsets of a surface (of revolution, or any other): depth is the distance to the reference surface on the
// volume's side; the surface at a depth is the reference surface offset by it, extended beyond the volume.
class OffsetFamily : public SlicingFamily {
public:
  OffsetFamily(const TopoDS_Face& reference, const Box& box) : box_(box) {
    Handle(Geom_Surface) surface = BRep_Tool::Surface(reference);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(reference, u0, u1, v0, v1);
    Eigen::Vector3d point;
    const Eigen::Vector3d inward = inwardNormalAtCentre(reference, point);
    gp_Pnt p;
    gp_Vec du, dv;
    surface->D1(0.5 * (u0 + u1), 0.5 * (v0 + v1), p, du, dv);
    const gp_Vec n = du.Crossed(dv);
    sign_ = (n.X() * inward.x() + n.Y() * inward.y() + n.Z() * inward.z()) > 0 ? 1.0 : -1.0;
    extended_ = extend(surface, u0, u1, v0, v1, box.size);
  }
  double depth(const gp_Pnt& p) const override {
    GeomAPI_ProjectPointOnSurf projection(p, extended_);
    if (projection.NbPoints() == 0) return std::numeric_limits<double>::infinity();
    return projection.LowerDistance();
  }
  TopoDS_Shape surfaceAt(double d) const override {
    Handle(Geom_Surface) offset = d == 0.0 ? extended_ : Handle(Geom_Surface)(new Geom_OffsetSurface(extended_, sign_ * d));
    return BRepBuilderAPI_MakeFace(offset, 1e-7).Face();
  }
  double pairCost() const override { return 0.2; }  // offset B-splines: the slowest to intersect
  SlicingSurface surfaceDescription(double d, int reference) const override {
    SlicingSurface s;
    s.kind = SurfaceKind::Other;
    s.referenceFace = reference;
    s.offset = d;
    return s;
  }

private:
  // The face's surface over its trimmed range, as a B-spline extended by `length` on every side (a surface of
  // revolution keeps its full turn).
  static Handle(Geom_Surface) extend(const Handle(Geom_Surface)& surface, double u0, double u1, double v0, double v1,
                                     double length) {
    Handle(Geom_Surface) basis = surface;
    if (surface->IsKind(STANDARD_TYPE(Geom_RectangularTrimmedSurface)))
      basis = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)->BasisSurface();
    Handle(Geom_BSplineSurface) spline =
        GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(basis, u0, u1, v0, v1));
    const bool closedU = surface->IsUPeriodic() || std::abs(u1 - u0 - 2.0 * M_PI) < 1e-6;
    for (const Standard_Boolean inU : {Standard_True, Standard_False}) {
      if (inU && closedU) continue;
      for (const Standard_Boolean after : {Standard_True, Standard_False}) {
        Handle(Geom_BoundedSurface) bounded = spline;
        GeomLib::ExtendSurfByLength(bounded, length, 1, inU, after);
        spline = Handle(Geom_BSplineSurface)::DownCast(bounded);
      }
    }
    return spline;
  }
  Handle(Geom_Surface) extended_;
  double sign_ = 1.0;
  Box box_;
};

// Offsets of a surface of revolution: exact, as the revolved offsets of its meridian. The depth of a point is
// its distance to the meridian in its meridian plane.
class RevolutionFamily : public SlicingFamily {
public:
  RevolutionFamily(const TopoDS_Face& reference, const gp_Ax1& axis, const Box& box)
      : meridian_(reference, toEigen(axis.Location().XYZ()), toEigen(axis.Direction().XYZ()), kMeridianSamples,
                  box.size),
        e1_(meridian_.axis().unitOrthogonal()), box_(box) {}
  double depth(const gp_Pnt& p) const override { return meridian_.distance(meridian_.plane(toEigen(p.XYZ()))); }
  TopoDS_Shape surfaceAt(double d) const override {
    // The offset meridian, fitted through the offset points, with straight extensions along its end
    // tangents beyond the volume (edges of their own: a fit through far-off points would swing, even across
    // the axis), revolved about the axis.
    const std::vector<Eigen::Vector2d>& samples = meridian_.samples();
    std::vector<Eigen::Vector2d> points;
    for (size_t i = 0; i < samples.size(); ++i) points.push_back(samples[i] + d * meridian_.sampleNormal(i));
    const Eigen::Vector2d first = (points[0] - points[1]).normalized(), last = (points.back() - points[points.size() - 2]).normalized();
    const Eigen::Vector3d& axisPoint = meridian_.axisPoint();
    const Eigen::Vector3d& axis = meridian_.axis();
    auto at = [&](const Eigen::Vector2d& q) {
      return toPoint(axisPoint + q.y() * axis + std::max(q.x(), 1e-3) * e1_);  // (ρ, z) in the plane of e1
    };
    // An extension stops at the axis: a meridian that reaches it closes the surface there.
    auto extended = [&](const Eigen::Vector2d& end, const Eigen::Vector2d& along) {
      const double length = along.x() < -1e-9 ? std::min(box_.size, (end.x() - 1e-3) / -along.x()) : box_.size;
      return end + length * along;
    };
    Handle(TColgp_HArray1OfPnt) poles = new TColgp_HArray1OfPnt(1, static_cast<int>(points.size()));
    for (size_t i = 0; i < points.size(); ++i) poles->SetValue(static_cast<int>(i) + 1, at(points[i]));
    GeomAPI_PointsToBSpline fit(poles->Array1(), 3, 5, GeomAbs_C2, 1e-4);
    if (!fit.IsDone())
      throw ComputationError("the offset of the surface of revolution by " + number(d) + " mm could not be fitted: "
                             "use a smaller step");
    BRepBuilderAPI_MakeWire wire;
    const gp_Pnt start = fit.Curve()->StartPoint(), end = fit.Curve()->EndPoint();
    const gp_Pnt before = at(extended(points.front(), first)), after = at(extended(points.back(), last));
    if (before.Distance(start) > 1e-6) wire.Add(BRepBuilderAPI_MakeEdge(before, start).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(fit.Curve()).Edge());
    if (after.Distance(end) > 1e-6) wire.Add(BRepBuilderAPI_MakeEdge(end, after).Edge());
    if (!wire.IsDone()) throw ComputationError("the offset meridian at " + number(d) + " mm is degenerate: use another step");
    BRepPrimAPI_MakeRevol revolve(wire.Wire(), gp_Ax1(toPoint(axisPoint), gp_Dir(axis.x(), axis.y(), axis.z())), 2.0 * M_PI);
    if (!revolve.IsDone())
      throw ComputationError("the offset meridian at " + number(d) + " mm could not be revolved: use another step");
    return revolve.Shape();
  }
  double pairCost() const override { return 0.066; }  // revolved B-splines (impeller S4 and S5)
  SlicingSurface surfaceDescription(double d, int reference) const override {
    SlicingSurface s;
    s.kind = SurfaceKind::Revolution;
    s.origin = meridian_.axisPoint();
    s.direction = meridian_.axis();
    s.referenceFace = reference;
    s.offset = d;
    return s;
  }

  // The meridian's normal into the volume, exact: a difference of the distance, which has no sign, would be
  // noise on the reference surface itself (slice 0).
  Eigen::Vector3d depthGradient(const Eigen::Vector3d& p, double) const override {
    const auto place = meridian_.locate(meridian_.plane(p));
    const Eigen::Vector2d n = meridian_.normal(place ? place->s : 0.0);
    Eigen::Vector3d radial = p - meridian_.axisPoint();
    radial -= meridian_.axis().dot(radial) * meridian_.axis();
    if (!(radial.norm() > 1e-12)) return Eigen::Vector3d::Zero();
    return (radial.normalized() * n.x() + meridian_.axis() * n.y()).normalized();
  }

private:
  Meridian meridian_;
  Eigen::Vector3d e1_;
  Box box_;
};

// Concentric spheres: exact offsets of a sphere (the revolved fit of a meridian through both poles is slow to
// split and can leave a surface uncut). Described as surfaces of revolution about the sphere's axis, so that the
// sweep follows the sphere's meridian.
class SphereFamily : public SlicingFamily {
public:
  // A whole sphere crosses any volume it reaches: no size to take from the volume.
  SphereFamily(const gp_Sphere& sphere, const Eigen::Vector3d& inward, const Eigen::Vector3d& onFace)
      : centre_(toEigen(sphere.Location().XYZ())), axis_(toEigen(sphere.Position().Direction().XYZ())),
        radius_(sphere.Radius()), sign_(inward.dot(onFace - centre_) > 0.0 ? 1.0 : -1.0) {}
  double depth(const gp_Pnt& p) const override { return sign_ * ((toEigen(p.XYZ()) - centre_).norm() - radius_); }
  TopoDS_Shape surfaceAt(double d) const override {
    const double r = radius_ + sign_ * d;
    if (!(r > 1e-6)) throw InputError("the concentric spheres reach the centre: use a larger step or another strategy");
    return BRepBuilderAPI_MakeFace(gp_Sphere(gp_Ax3(toPoint(centre_), gp_Dir(axis_.x(), axis_.y(), axis_.z())), r)).Face();
  }
  SlicingSurface surfaceDescription(double d, int reference) const override {
    SlicingSurface s;
    s.kind = SurfaceKind::Revolution;
    s.origin = centre_;
    s.direction = axis_;
    s.radius = radius_ + sign_ * d;
    s.referenceFace = reference;
    s.offset = d;
    return s;
  }
  Eigen::Vector3d depthGradient(const Eigen::Vector3d& p, double) const override {
    const Eigen::Vector3d radial = p - centre_;
    if (!(radial.norm() > 1e-12)) return Eigen::Vector3d::Zero();
    return sign_ * radial.normalized();
  }

private:
  Eigen::Vector3d centre_, axis_;
  double radius_, sign_;
};

}  // namespace

std::pair<double, double> SlicingFamily::depthRange(const TopoDS_Shape& solid) const {
  // On a mesh of a copy: the solid shares its faces with the part, and a finer mesh made of them before (a
  // clearance check's) would move the slices.
  const Box box = boxOf(solid);
  const geometry::TriangleMesh mesh = geometry::meshFacesAfresh(solid, 1e-3 * box.size);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Eigen::Vector3d& p : mesh.vertices) {
    const double d = depth(toPoint(p));
    low = std::min(low, d);
    high = std::max(high, d);
  }
  if (!std::isfinite(low) || !std::isfinite(high)) throw ComputationError("the volume could not be meshed to measure it");
  return {low, high};
}

void SlicingFamily::axisField(const TopoDS_Shape& slice, double d, std::vector<Eigen::Vector3d>& points,
                              std::vector<Eigen::Vector3d>& directions) const {
  // Mesh nodes of the slice that lie on its slicing surface, at most about 50, with the depth's gradient
  // reversed there: the tool axis points out of the volume, towards the reference surface.
  const Box box = boxOf(slice);
  geometry::meshShape(slice, 2e-3 * box.size, 0.3, false);
  std::vector<Eigen::Vector3d> on;
  for (TopExp_Explorer it(slice, TopAbs_FACE); it.More(); it.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(TopoDS::Face(it.Current()), location);
    if (mesh.IsNull()) continue;
    for (int i = 1; i <= mesh->NbNodes(); ++i) {
      const gp_Pnt p = mesh->Node(i).Transformed(location.Transformation());
      if (std::abs(depth(p) - d) < 1e-4 * std::max(1.0, box.size)) on.push_back(toEigen(p.XYZ()));
    }
  }
  const size_t stride = std::max<size_t>(1, on.size() / 50);
  const double h = 1e-3 * std::max(1.0, box.size);
  for (size_t i = 0; i < on.size(); i += stride) {
    const Eigen::Vector3d gradient = depthGradient(on[i], h);
    if (!(gradient.norm() > 1e-12) || !gradient.allFinite()) continue;
    points.push_back(on[i]);
    directions.push_back(-gradient.normalized());
  }
}

Eigen::Vector3d SlicingFamily::depthGradient(const Eigen::Vector3d& p, double h) const {
  Eigen::Vector3d gradient;
  for (int k = 0; k < 3; ++k) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[k] = h;
    gradient[k] = (depth(toPoint(p + e)) - depth(toPoint(p - e))) / (2.0 * h);
  }
  return gradient;
}

std::unique_ptr<SlicingFamily> planesAlong(const TopoDS_Shape& solid, const Eigen::Vector3d& normal) {
  const Box box = boxOf(solid);
  return std::make_unique<PlaneFamily>(box.centre, normal, box);
}

std::unique_ptr<SlicingFamily> familyOf(const TopoDS_Shape& solid, const TopoDS_Face& reference, Strategy strategy) {
  const Box box = boxOf(solid);
  Eigen::Vector3d point;
  const Eigen::Vector3d inward = inwardNormalAtCentre(reference, point);
  const BRepAdaptor_Surface surface(reference);
  const bool plane = surface.GetType() == GeomAbs_Plane, cylinder = surface.GetType() == GeomAbs_Cylinder;
  if (strategy == Strategy::PlanesParallelToFace || plane) return std::make_unique<PlaneFamily>(point, inward, box);
  if (strategy == Strategy::CoaxialCylinders || cylinder) {
    const gp_Cylinder c = surface.Cylinder();
    const Eigen::Vector3d axisPoint = toEigen(c.Axis().Location().XYZ()), axis = toEigen(c.Axis().Direction().XYZ());
    Eigen::Vector3d radial = point - axisPoint;
    radial -= axis.dot(radial) * axis;
    return std::make_unique<CylinderFamily>(c.Axis(), c.Radius(), inward.dot(radial) < 0.0, box);
  }
  if (surface.GetType() == GeomAbs_SurfaceOfRevolution)
    return std::make_unique<RevolutionFamily>(reference, surface.AxeOfRevolution(), box);
  // A torus is a surface of revolution too: offsets of its meridian, where the general offset surface would
  // make OCCT's splitter intersect offset B-splines (minutes, then invalid slices).
  if (surface.GetType() == GeomAbs_Cone) return std::make_unique<RevolutionFamily>(reference, surface.Cone().Axis(), box);
  if (surface.GetType() == GeomAbs_Sphere) return std::make_unique<SphereFamily>(surface.Sphere(), inward, point);
  if (surface.GetType() == GeomAbs_Torus)
    return std::make_unique<RevolutionFamily>(reference, surface.Torus().Axis(), box);
  return std::make_unique<OffsetFamily>(reference, box);
}

}  // namespace hsm::roughing
