#include "geometry/mesh.hpp"
#include "common/fork_safety.hpp"

#include "common/error.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <RWStl.hxx>
#include <Standard_Failure.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <TopExp_Explorer.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <list>
#include <mutex>
#include <sstream>

namespace hsm::geometry {

Eigen::AlignedBox3d TriangleMesh::bounds() const {
  Eigen::AlignedBox3d box;
  for (const auto& v : vertices) box.extend(v);
  return box;
}

namespace {
// OCCT's mesher asks its progress indicator whether to stop between nodes and faces, from every thread it
// runs on: this one says stop once the time is up.
class Deadline : public Message_ProgressIndicator {
public:
  explicit Deadline(double seconds)
      : end_(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                    std::chrono::duration<double>(seconds))) {}
  bool passed() const { return passed_; }

protected:
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {}
  Standard_Boolean UserBreak() override {
    if (!passed_ && std::chrono::steady_clock::now() > end_) passed_ = true;
    return passed_;
  }

private:
  std::chrono::steady_clock::time_point end_;
  std::atomic<bool> passed_{false};
};
}  // namespace

void meshShape(const TopoDS_Shape& shape, double deflection, double angle, bool parallel, double seconds) {
  IMeshTools_Parameters parameters;
  parameters.Deflection = deflection;
  parameters.Angle = angle;
  parameters.Relative = Standard_False;
  parameters.InParallel = parallel;
  Handle(Deadline) deadline = new Deadline(seconds);
  BRepMesh_IncrementalMesh(shape, parameters, deadline->Start());
  if (deadline->passed())
    throw ComputationError("OCCT's mesher had not meshed the faces (within " + std::to_string(deflection) +
                           " mm) after " + std::to_string(static_cast<int>(seconds)) + " s and was stopped: a "
                           "face is probably malformed; check the shape (FreeCAD: Part > Check geometry) and "
                           "refine or rebuild the faces it names");
}

TriangleMesh meshFaces(const TopoDS_Shape& shape, double deflection, const std::vector<int>& faces,
                       double seconds) {
  if (!(deflection > 0.0)) throw InputError("mesh deflection must be positive, got " + std::to_string(deflection));
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  std::vector<int> wanted = faces;
  if (wanted.empty())
    for (int i = 1; i <= map.Extent(); ++i) wanted.push_back(i);
  // Only the faces asked for are meshed (a compound of them), in parallel where OCCT safely can.
  BRep_Builder builder;
  TopoDS_Compound selected;
  builder.MakeCompound(selected);
  for (int index : wanted) {
    if (index < 1 || index > map.Extent())
      throw InputError("face " + std::to_string(index) + " does not exist: the shape has " +
                       std::to_string(map.Extent()) + " faces");
    builder.Add(selected, map(index));
  }
  meshShape(selected, deflection, 0.5, occtMayRunInParallel(), seconds);
  TriangleMesh mesh;
  for (int index : wanted) {
    const TopoDS_Face face = TopoDS::Face(map(index));
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(face, location);
    if (triangulation.IsNull()) throw ComputationError("OCCT could not mesh face " + std::to_string(index));
    const gp_Trsf transform = location.Transformation();
    const int offset = static_cast<int>(mesh.vertices.size());
    for (int i = 1; i <= triangulation->NbNodes(); ++i) {
      const gp_Pnt p = triangulation->Node(i).Transformed(transform);
      mesh.vertices.emplace_back(p.X(), p.Y(), p.Z());
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int i = 1; i <= triangulation->NbTriangles(); ++i) {
      int a, b, c;
      triangulation->Triangle(i).Get(a, b, c);
      if (reversed) std::swap(b, c);
      mesh.triangles.emplace_back(offset + a - 1, offset + b - 1, offset + c - 1);
      mesh.faceOf.push_back(index);
    }
  }
  return mesh;
}

namespace {
struct KeptMesh {
  size_t hash;
  std::string brep;  // compared in full on a hit: two parts never share a mesh by a hash collision
  double deflection;
  TriangleMesh mesh;
  // Meshing leaves its triangulations on the faces, and what runs after reads them (a bounding box of the
  // part is the triangulation's where there is one: the rapids' safe height): a hit puts them back.
  std::vector<std::pair<int, Handle(Poly_Triangulation)>> triangulations;
};
constexpr size_t kKeptMeshes = 4;  // a part or two in a session: a few MB each

std::string facesBrep(const TopTools_IndexedMapOfShape& map, const std::vector<int>& faces) {
  BRep_Builder builder;
  TopoDS_Compound selected;
  builder.MakeCompound(selected);
  for (int index = 1; index <= map.Extent(); ++index)
    if (faces.empty() || std::find(faces.begin(), faces.end(), index) != faces.end()) builder.Add(selected, map(index));
  std::ostringstream text;
  text << map.Extent() << ':';  // the numbers the faces were taken by (empty: all, as meshFaces reads it)
  for (int index : faces) text << ' ' << index;
  text << '\n';
  BRepTools::Write(selected, text);
  return text.str();
}
}  // namespace

TriangleMesh meshFacesKept(const TopoDS_Shape& shape, double deflection, const std::vector<int>& faces,
                           double seconds) {
  static std::mutex mutex;
  static std::list<KeptMesh> kept;  // most recent first
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  std::string brep = facesBrep(map, faces);
  const size_t hash = std::hash<std::string>{}(brep);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if (it->hash == hash && it->deflection == deflection && it->brep == brep) {
        kept.splice(kept.begin(), kept, it);
        BRep_Builder builder;
        for (const auto& [index, triangulation] : it->triangulations)
          builder.UpdateFace(TopoDS::Face(map(index)), triangulation);
        return it->mesh;
      }
  }
  TriangleMesh mesh = meshFaces(shape, deflection, faces, seconds);  // outside the lock: meshing takes its time
  std::vector<std::pair<int, Handle(Poly_Triangulation)>> triangulations;
  for (int index = 1; index <= map.Extent(); ++index) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) triangulation = BRep_Tool::Triangulation(TopoDS::Face(map(index)), location);
    if (!triangulation.IsNull()) triangulations.emplace_back(index, triangulation);
  }
  const std::lock_guard<std::mutex> lock(mutex);
  kept.push_front({hash, std::move(brep), deflection, mesh, std::move(triangulations)});
  if (kept.size() > kKeptMeshes) kept.pop_back();
  return mesh;
}

TriangleMesh meshFacesAfresh(const TopoDS_Shape& shape, double deflection) {
  return meshFaces(BRepBuilderAPI_Copy(shape, Standard_True, Standard_False).Shape(), deflection);
}

void addFaceBoundary(TriangleMesh& mesh, const TopoDS_Shape& shape, int face, double spacing) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  if (face < 1 || face > faces.Extent()) throw InputError("face " + std::to_string(face) + " does not exist");
  for (TopExp_Explorer it(faces(face), TopAbs_EDGE); it.More(); it.Next()) {
    BRepAdaptor_Curve curve(TopoDS::Edge(it.Current()));
    const double length = GCPnts_AbscissaPoint::Length(curve);
    const int count = std::max(2, static_cast<int>(std::ceil(length / spacing)) + 1);
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k < count; ++k) {
      const gp_Pnt p = curve.Value(curve.FirstParameter() + (curve.LastParameter() - curve.FirstParameter()) * k / (count - 1));
      points.emplace_back(p.X(), p.Y(), p.Z());
    }
    mesh.polylines.push_back(std::move(points));
    mesh.polylineFace.push_back(face);
  }
}

TriangleMesh readStl(const std::string& path) {
  if (!std::ifstream(path, std::ios::binary)) throw InputError("cannot read the STL file '" + path + "': check the path");
  Handle(Poly_Triangulation) triangulation;
  try {
    triangulation = RWStl::ReadFile(path.c_str());
  } catch (const Standard_Failure& failure) {
    throw InputError(path + ": not a readable STL file (" + failure.GetMessageString() + ")");
  }
  if (triangulation.IsNull() || triangulation->NbTriangles() == 0)
    throw InputError(path + ": no triangle found (neither binary nor ASCII STL)");
  TriangleMesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(triangulation->NbNodes()));
  for (int i = 1; i <= triangulation->NbNodes(); ++i) {
    const gp_Pnt p = triangulation->Node(i);
    mesh.vertices.emplace_back(p.X(), p.Y(), p.Z());
  }
  for (int i = 1; i <= triangulation->NbTriangles(); ++i) {
    int a, b, c;
    triangulation->Triangle(i).Get(a, b, c);
    mesh.triangles.emplace_back(a - 1, b - 1, c - 1);
    mesh.faceOf.push_back(0);
  }
  return mesh;
}

std::vector<int> faceAndNeighbours(const TopoDS_Shape& solid, int face) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  if (face < 1 || face > faces.Extent())
    throw InputError("face " + std::to_string(face) + " does not exist: the shape has " +
                     std::to_string(faces.Extent()) + " faces");
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  std::vector<int> result{face};
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(faces(face), TopAbs_EDGE, edges);
  for (int e = 1; e <= edges.Extent(); ++e) {
    const int index = edgeFaces.FindIndex(edges(e));
    if (index == 0) continue;
    for (const TopoDS_Shape& neighbour : edgeFaces(index)) {
      const int n = faces.FindIndex(neighbour);
      if (n > 0 && std::find(result.begin(), result.end(), n) == result.end()) result.push_back(n);
    }
  }
  return result;
}

}  // namespace hsm::geometry
