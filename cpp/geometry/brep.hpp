// BREP in and out: shapes cross the FreeCAD/core boundary as BREP text (Shape.exportBrepToString()).
#pragma once

#include <Eigen/Geometry>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <string_view>

namespace hsm::geometry {

// Reads OCCT BREP text; throws InputError if the text is empty or not a BREP shape.
TopoDS_Shape readBrep(std::string_view text);

// Writes OCCT BREP text that FreeCAD's Part.Shape().importBrepFromString() reads back.
std::string writeBrep(const TopoDS_Shape& shape);

// The one face of a shape (a face, or a shell/compound holding exactly one face); InputError otherwise.
TopoDS_Face singleFace(const TopoDS_Shape& shape);

struct ShapeSummary {
  int solids = 0;
  int shells = 0;
  int faces = 0;
  int wires = 0;
  int edges = 0;
  int vertices = 0;
  double volume = 0.0;   // mm^3, 0 for shapes without solids
  double area = 0.0;     // mm^2, total face area
  double length = 0.0;   // mm, total edge length
  Eigen::AlignedBox3d bounds;  // empty for an empty shape
  bool valid = false;    // BRepCheck_Analyzer verdict
};

// Counts the topology (each sub-shape once) and measures volume, area, edge length and bounds.
ShapeSummary summarize(const TopoDS_Shape& shape);

}  // namespace hsm::geometry
