#include "roughing/parts.hpp"

#include "common/error.hpp"
#include "common/text.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <Geom_Ellipse.hxx>
#include <gp_Elips.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopTools_ListOfShape.hxx>
#include <gp_Ax2.hxx>

#include <cmath>
#include <functional>

namespace hsm::roughing {

namespace {

constexpr double kLargestPart = 1000.0;  // mm: a test part's sizes; larger ones only cost time (minutes)

void positive(double value, const std::string& what) {
  if (!(value > 0.0) || !std::isfinite(value)) throw InputError(what + " = " + number(value) + " must be positive (mm)");
  if (value > kLargestPart)
    throw InputError(what + " = " + number(value) + " mm is larger than a test part's " + number(kLargestPart) + " mm");
}

// An angle of the part's shape, in degrees, within [low, high] (beyond, the shape is not the part any more).
void angleWithin(double value, double low, double high, const std::string& what, const std::string& why) {
  if (!(value >= low && value <= high))
    throw InputError(what + " = " + number(value) + "° must be in [" + number(low) + "°, " + number(high) + "°]: " + why);
}

double volumeOf(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  return props.Mass();
}

TopoDS_Shape unified(const TopoDS_Shape& shape) {
  ShapeUpgrade_UnifySameDomain unify(shape, Standard_True, Standard_True, Standard_False);
  unify.Build();
  return unify.Shape();
}

// The quarter ellipse of the meridian plane y = 0 about `centre`, x = centre − a·cos t, z = centre − b·sin t
// for t in [0, π/2], as an exact arc (its surface of revolution is exact, and cheaper for the booleans than an
// interpolated curve's).
TopoDS_Edge meridianArc(const gp_Pnt& centre, double a, double b) {
  if (a >= b) {  // major axis along −X: P(u) = C + a·cos u·(−X) + b·sin u·(−Z), u = t
    const gp_Elips ellipse(gp_Ax2(centre, -gp::DY(), -gp::DX()), a, b);
    return BRepBuilderAPI_MakeEdge(new Geom_Ellipse(ellipse), 0.0, 0.5 * M_PI).Edge();
  }
  // major axis along −Z: P(u) = C + b·cos u·(−Z) + a·sin u·(−X), u = π/2 − t
  const gp_Elips ellipse(gp_Ax2(centre, gp::DY(), -gp::DZ()), b, a);
  return BRepBuilderAPI_MakeEdge(new Geom_Ellipse(ellipse), 0.0, 0.5 * M_PI).Edge();
}

// The solid of revolution about Z of the region bounded by the polyline `before`, the meridian curve from its
// last point to `after`'s first, the polyline `after`, and back to `before`'s first point.
TopoDS_Shape revolved(const std::vector<gp_Pnt>& before, const TopoDS_Edge& curve, const std::vector<gp_Pnt>& after) {
  BRepBuilderAPI_MakeWire wire;
  for (size_t i = 0; i + 1 < before.size(); ++i) wire.Add(BRepBuilderAPI_MakeEdge(before[i], before[i + 1]).Edge());
  wire.Add(curve);
  for (size_t i = 0; i + 1 < after.size(); ++i) wire.Add(BRepBuilderAPI_MakeEdge(after[i], after[i + 1]).Edge());
  wire.Add(BRepBuilderAPI_MakeEdge(after.back(), before.front()).Edge());
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(wire.Wire(), Standard_True).Face();
  return BRepPrimAPI_MakeRevol(face, gp::OZ(), 2.0 * M_PI).Shape();
}

}  // namespace

PartAndStock slantedSlotBlock(const SlantedSlotParameters& p) {
  positive(p.length, "length");
  positive(p.width, "width");
  positive(p.height, "height");
  positive(p.slotWidth, "slot width");
  positive(p.slotDepth, "slot depth");
  if (!(p.tiltDeg >= 0.0 && p.tiltDeg < 60.0)) throw InputError("tilt " + number(p.tiltDeg) + "° must be in [0°, 60°)");
  const double t = p.tiltDeg * M_PI / 180.0;
  const gp_Dir axis(std::sin(t), 0.0, std::cos(t)), across(std::cos(t), 0.0, -std::sin(t));
  const gp_Pnt mouth(0.5 * p.length, 0.0, p.height);
  // The floor must stay inside the box and the mouth on its top face.
  const double lowest = p.height - p.slotDepth * std::cos(t) - 0.5 * p.slotWidth * std::sin(t);
  if (!(lowest > 0.0) || p.slotDepth * std::sin(t) + 0.5 * p.slotWidth + 1.0 > 0.5 * p.length)
    throw InputError("the slot (" + number(p.slotWidth) + " × " + number(p.slotDepth) + " mm at " + number(p.tiltDeg) +
                     "°) does not fit in the block: make it smaller or the block larger");
  PartAndStock r;
  r.stock = BRepPrimAPI_MakeBox(p.length, p.width, p.height).Shape();
  const double above = p.slotWidth + p.height;  // the slot's prism goes well above the top face
  const gp_Pnt corner = mouth.Translated(-0.5 * p.slotWidth * gp_Vec(across) - gp_Vec(0.0, 1.0, 0.0) - p.slotDepth * gp_Vec(axis));
  const TopoDS_Shape slot =
      BRepPrimAPI_MakeBox(gp_Ax2(corner, axis, across), p.slotWidth, p.width + 2.0, p.slotDepth + above).Shape();
  BRepAlgoAPI_Cut cut(r.stock, slot);
  if (!cut.IsDone()) throw ComputationError("the slanted slot block could not be built");
  r.part = unified(cut.Shape());
  return r;
}

double slantedSlotVolume(const SlantedSlotParameters& p) { return p.slotWidth * p.slotDepth * p.width; }

PartAndStock impeller(const ImpellerParameters& p) {
  if (p.blades < 2 || p.blades > 24) throw InputError("blades = " + std::to_string(p.blades) + ": give 2 to 24 blades");
  positive(p.hubInletRadius, "hub inlet radius");
  positive(p.height, "height");
  positive(p.channelHeight, "channel height");
  positive(p.thickness, "blade thickness");
  positive(p.baseThickness, "base thickness");
  positive(p.outletRadius, "outlet radius");
  // Beyond these the blades leave the channel (a lean past 30°: no blade between hub and shroud, the boolean
  // gives nothing or the blank), or wrap about the axis so far that the booleans take minutes.
  angleWithin(p.leanDeg, -30.0, 30.0, "blade lean", "the blade must stand between hub and shroud (the paper's 20°)");
  angleWithin(p.wrapDeg, -120.0, 120.0, "blade wrap", "a blade turns at most a third of a turn from inlet to outlet");
  if (p.outletRadius > 20.0 * p.hubInletRadius)
    throw InputError("outlet radius " + number(p.outletRadius) + " mm is more than 20 times the hub inlet radius " +
                     number(p.hubInletRadius) + " mm: the blades would be slivers at the inlet");
  const double a = p.outletRadius - p.hubInletRadius, b = p.height, h = p.channelHeight;
  if (!(a > h && b > h)) throw InputError("the channel height must be less than the hub's radial and axial extent");
  if (!(p.thickness * p.blades < 2.0 * M_PI * p.hubInletRadius * 0.5))
    throw InputError("the blades are too thick for the inlet: thinner blades or fewer");
  // The hub and shroud meridians: quarter ellipses about (outletRadius, height), from the inlet (t = 0) to the
  // outlet (t = π/2); the shroud is the hub's brought in by the channel height on both axes.
  auto hub = [&](double t) { return gp_Pnt(p.outletRadius - a * std::cos(t), 0.0, p.height - b * std::sin(t)); };
  auto shroud = [&](double t) {
    return gp_Pnt(p.outletRadius - (a - h) * std::cos(t), 0.0, p.height - (b - h) * std::sin(t));
  };
  const double base = -p.baseThickness, half = 0.5 * M_PI;
  // The blank: inlet plane, shroud (its skin), outlet cylinder, base, about the axis.
  const TopoDS_Shape blank =
      revolved({gp_Pnt(0, 0, base), gp_Pnt(p.outletRadius, 0, base), shroud(half)}, meridianArc(gp_Pnt(p.outletRadius, 0.0, p.height), a - h, b - h),
               {shroud(0.0), gp_Pnt(0, 0, p.height)});
  const TopoDS_Shape hubBody =
      revolved({gp_Pnt(0, 0, base), gp_Pnt(p.outletRadius, 0, base), hub(half)}, meridianArc(gp_Pnt(p.outletRadius, 0.0, p.height), a, b),
               {hub(0.0), gp_Pnt(0, 0, p.height)});
  // Blades: sections across the channel (hub to beyond the shroud) at stations along the flow, each a thin
  // quadrilateral at the angle θ(t, s) = θ_k + wrap·t/(π/2) + lean·s, lofted into a solid.
  TopTools_ListOfShape blades;
  const double lean = p.leanDeg * M_PI / 180.0, wrap = p.wrapDeg * M_PI / 180.0;
  for (int k = 0; k < p.blades; ++k) {
    BRepOffsetAPI_ThruSections loft(Standard_True, Standard_False, 1e-6);
    for (int i = 0; i <= 6; ++i) {
      const double t = -0.15 + (half + 0.3) * i / 6.0;
      const gp_Pnt hp = hub(t), sp = shroud(t);
      auto corner = [&](double s, double side) {
        const double r = hp.X() + s * (sp.X() - hp.X()), z = hp.Z() + s * (sp.Z() - hp.Z());
        const double theta = 2.0 * M_PI * k / p.blades + wrap * t / half + lean * s + side * 0.5 * p.thickness / r;
        return gp_Pnt(r * std::cos(theta), r * std::sin(theta), z);
      };
      loft.AddWire(BRepBuilderAPI_MakePolygon(corner(-0.3, -1), corner(-0.3, 1), corner(1.3, 1), corner(1.3, -1),
                                              Standard_True).Wire());
    }
    loft.Build();
    if (!loft.IsDone()) throw ComputationError("blade " + std::to_string(k + 1) + " of the impeller could not be lofted");
    blades.Append(loft.Shape());
  }
  BRepAlgoAPI_Fuse fuse;
  TopTools_ListOfShape arguments;
  arguments.Append(hubBody);
  fuse.SetArguments(arguments);
  fuse.SetTools(blades);
  fuse.Build();
  if (!fuse.IsDone() || fuse.HasErrors()) throw ComputationError("the impeller's hub and blades could not be fused");
  BRepAlgoAPI_Common common(fuse.Shape(), blank);
  if (!common.IsDone() || common.HasErrors()) throw ComputationError("the impeller could not be trimmed to its blank");
  PartAndStock r;
  r.part = unified(common.Shape());
  r.stock = blank;
  // What the booleans gave is an impeller: a hub with blades on it, inside its blank and not the blank.
  const double part = volumeOf(r.part), hubOnly = volumeOf(BRepAlgoAPI_Common(hubBody, blank).Shape()), stock = volumeOf(blank);
  if (!(part > hubOnly * (1.0 + 1e-4) && part < stock * (1.0 - 1e-4)))
    throw ComputationError("the impeller built with these parameters has no blades between hub and shroud (part " +
                           number(part) + " mm³, hub " + number(hubOnly) + " mm³, blank " + number(stock) +
                           " mm³): a smaller lean or wrap, thinner blades");
  return r;
}

}  // namespace hsm::roughing
