#include "geometry/wire.hpp"

#include "common/error.hpp"

#include <BRepBuilderAPI_MakeWire.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>

#include <string>

namespace hsm::geometry {

namespace {
// Chord tolerance used to decide whether two edge ends touch when chaining a compound of edges.
constexpr double kChainTolerance = 1e-4;  // mm
}  // namespace

TopoDS_Wire toWire(const TopoDS_Shape& curve) {
  if (curve.IsNull()) throw InputError("curve shape is null: pass an edge or a wire");
  if (curve.ShapeType() == TopAbs_WIRE) return TopoDS::Wire(curve);
  // A face's edges form its outline, never a guide by themselves: taking them would silently machine
  // along the whole outline.
  if (TopExp_Explorer(curve, TopAbs_FACE).More())
    throw InputError("the curve is a face (or holds faces): pick the boundary edge(s) of the face, not the face");

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

}  // namespace hsm::geometry
