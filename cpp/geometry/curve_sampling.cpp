#include "geometry/curve_sampling.hpp"

#include "common/error.hpp"

#include <BRepAdaptor_CompCurve.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>

#include <string>

namespace hsm::geometry {

namespace {
// Chord tolerance used to decide whether two edge ends touch when chaining a compound of edges.
constexpr double kChainTolerance = 1e-4;  // mm
// Below this length a curve cannot carry toolpath points.
constexpr double kMinCurveLength = 1e-6;  // mm
}  // namespace

TopoDS_Wire toWire(const TopoDS_Shape& curve) {
  if (curve.IsNull()) throw InputError("curve shape is null: pass an edge or a wire");
  if (curve.ShapeType() == TopAbs_WIRE) return TopoDS::Wire(curve);

  Handle(TopTools_HSequenceOfShape) edges = new TopTools_HSequenceOfShape;
  for (TopExp_Explorer it(curve, TopAbs_EDGE); it.More(); it.Next()) edges->Append(it.Current());
  if (edges->IsEmpty())
    throw InputError("curve shape has no edge: pass an edge, a wire or a compound of connected edges");
  if (edges->Length() == 1) return BRepBuilderAPI_MakeWire(TopoDS::Edge(edges->First())).Wire();

  // ConnectEdgesToWires orders the edges of an unordered compound into chains.
  Handle(TopTools_HSequenceOfShape) wires;
  ShapeAnalysis_FreeBounds::ConnectEdgesToWires(edges, kChainTolerance, false, wires);
  if (wires.IsNull() || wires->Length() != 1)
    throw InputError("curve edges do not form one connected chain (" +
                     std::to_string(wires.IsNull() ? 0 : wires->Length()) +
                     " pieces): pass edges that meet end to end");
  return TopoDS::Wire(wires->First());
}

PointArray sampleByArcLength(const TopoDS_Shape& curve, int count) {
  if (count < 2) throw InputError("sample count is " + std::to_string(count) + ": ask for at least 2 points");
  const TopoDS_Wire wire = toWire(curve);
  try {
    BRepAdaptor_CompCurve adaptor(wire, /*KnotByCurvilinearAbcissa=*/false);
    const double length = GCPnts_AbscissaPoint::Length(adaptor);
    if (!(length > kMinCurveLength))
      throw InputError("curve has zero length: pass an edge or wire with distinct end points");
    GCPnts_UniformAbscissa uniform(adaptor, count);
    if (!uniform.IsDone() || uniform.NbPoints() != count)
      throw ComputationError("OCCT could not place " + std::to_string(count) + " equally spaced points on the curve");
    PointArray points(count, 3);
    for (int i = 0; i < count; ++i) {
      const gp_Pnt p = adaptor.Value(uniform.Parameter(i + 1));
      points.row(i) << p.X(), p.Y(), p.Z();
    }
    return points;
  } catch (const Standard_Failure& failure) {
    throw ComputationError(std::string("OCCT failed while sampling the curve: ") + failure.GetMessageString());
  }
}

}  // namespace hsm::geometry
