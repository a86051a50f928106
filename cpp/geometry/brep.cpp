#include "geometry/brep.hpp"
#include "geometry/bounds.hpp"

#include "common/error.hpp"
#include "common/occt_guard.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <sstream>

namespace hsm::geometry {

TopoDS_Shape readBrep(std::string_view text) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw InputError("BREP text is empty: pass Shape.exportBrepToString() of a non-empty shape");
  std::istringstream stream{std::string(text)};
  // OCCT's reader loops for ever on some malformed text, reading from a stream that has failed (found by
  // fuzzing): a failed read throws here instead, and ends the reading.
  stream.exceptions(std::ios::failbit | std::ios::badbit);
  TopoDS_Shape shape;
  BRep_Builder builder;
  try {
    // OCCT's reader also dereferences null geometry on some malformed text (a trimmed curve whose basis
    // is missing, found by fuzzing): it runs guarded, so that the signal becomes an error.
    guarded("reading of the BREP text", [&] {
      BRepTools::Read(shape, stream, builder);
      return 0;
    });
  } catch (const ComputationError& error) {
    throw InputError(std::string("BREP text could not be read: ") + error.what());
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("BREP text could not be read (") + failure.GetMessageString() +
                     "): pass the unmodified output of Shape.exportBrepToString()");
  } catch (const std::ios_base::failure&) {
    throw InputError("BREP text is malformed near character " + std::to_string(long(stream.rdbuf()->pubseekoff(
                         0, std::ios::cur, std::ios::in))) + ": pass the unmodified output of Shape.exportBrepToString()");
  }
  if (shape.IsNull())
    throw InputError("BREP text holds no shape: pass the unmodified output of Shape.exportBrepToString()");
  return shape;
}

std::string writeBrep(const TopoDS_Shape& shape) {
  std::ostringstream stream;
  BRepTools::Write(shape, stream);
  return stream.str();
}

TopoDS_Face singleFace(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  if (!shape.IsNull()) TopExp::MapShapes(shape, TopAbs_FACE, faces);
  if (faces.Extent() != 1)
    throw InputError("expected one face, the shape has " + std::to_string(faces.Extent()) +
                     ": pass the bottom face itself (e.g. obj.Shape.getElement('Face4'))");
  return TopoDS::Face(faces(1));
}

namespace {
int countSubShapes(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, type, map);
  return map.Extent();
}
}  // namespace

ShapeSummary summarize(const TopoDS_Shape& shape) {
  ShapeSummary summary;
  if (shape.IsNull()) return summary;
  summary.solids = countSubShapes(shape, TopAbs_SOLID);
  summary.shells = countSubShapes(shape, TopAbs_SHELL);
  summary.faces = countSubShapes(shape, TopAbs_FACE);
  summary.wires = countSubShapes(shape, TopAbs_WIRE);
  summary.edges = countSubShapes(shape, TopAbs_EDGE);
  summary.vertices = countSubShapes(shape, TopAbs_VERTEX);

  GProp_GProps props;
  if (summary.solids > 0) {
    // Adaptive integration to a relative 1e-7: the fixed Gauss order of the plain call is 0.06 % off on the
    // master feature's B-spline faces (530,319 against 530,018.7 mm3) and moves with their parametrisation.
    BRepGProp::VolumeProperties(shape, props, 1e-7);
    summary.volume = props.Mass();
  }
  if (summary.faces > 0) {
    GProp_GProps surface;
    BRepGProp::SurfaceProperties(shape, surface);
    summary.area = surface.Mass();
  }
  // Each edge once: BRepGProp::LinearProperties on the whole shape would count shared edges per face.
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    GProp_GProps linear;
    BRepGProp::LinearProperties(edges(i), linear);
    summary.length += linear.Mass();
  }
  Bnd_Box box = geometry::exactBounds(shape);
  if (!box.IsVoid()) {
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    summary.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1));
  }
  summary.valid = BRepCheck_Analyzer(shape).IsValid();
  return summary;
}

}  // namespace hsm::geometry
