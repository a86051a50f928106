// Triangle meshes: of the faces of a shape (what a cutter must not gouge), and read from STL files.
#pragma once

#include <Eigen/Geometry>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace hsm::geometry {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<int> faceOf;  // per triangle: index of the source face (1-based, FreeCAD's FaceN), 0 if unknown
  // Polylines the tool must not cross either (edges sampled finely), with their face number.
  std::vector<std::vector<Eigen::Vector3d>> polylines;
  std::vector<int> polylineFace;

  Eigen::AlignedBox3d bounds() const;
};

// How long OCCT's mesher may take over one call before it is stopped: real parts mesh in seconds (the impeller
// at 0.001 mm, 906,000 triangles, in 14 s), but a malformed face can keep OCCT 7.9's Delaunay inserting nodes
// for ever.
constexpr double kMeshSeconds = 120.0;

// OCCT's mesh of `shape` (BRepMesh_IncrementalMesh: `deflection` mm chordal, `angle` rad, in parallel where
// asked), stopped after `seconds`: then a ComputationError says so and what to check.
void meshShape(const TopoDS_Shape& shape, double deflection, double angle, bool parallel,
               double seconds = kMeshSeconds);

// Tessellates the faces of `shape` within `deflection` mm (chordal) and 0.5 rad (angular). Faces are
// numbered as FreeCAD numbers them (Face1, Face2… in TopExp order); `faces` selects some (empty: all).
TriangleMesh meshFaces(const TopoDS_Shape& shape, double deflection, const std::vector<int>& faces = {},
                       double seconds = kMeshSeconds);
// The same on a copy of the shape's geometry: OCCT keeps a shape's finest triangulation, so meshFaces gives
// what the shape was meshed with before when that was finer; this one depends on `deflection` alone (a
// result that must not depend on what ran before: the roughing's setup search and sweeps).
TriangleMesh meshFacesAfresh(const TopoDS_Shape& shape, double deflection);

// meshFaces with its last few results kept, by the exact BREP text of the faces asked for (their geometry and
// any triangulation they carry: the state meshFaces starts from) and the deflection: the same part finished
// again — a study's next variant, a preview after K changed — is not meshed again (meshing was 38 % of a
// finishing). The mesh is the one meshFaces gives the same faces in the same state; thread-safe.
TriangleMesh meshFacesKept(const TopoDS_Shape& shape, double deflection, const std::vector<int>& faces,
                           double seconds = kMeshSeconds);

// The boundary edges of face `face` of `shape` as polylines with chords of at most `spacing` mm.
void addFaceBoundary(TriangleMesh& mesh, const TopoDS_Shape& shape, int face, double spacing);

// Reads an STL file, binary or ASCII (OCCT's RWStl: coincident corners merged into shared vertices);
// InputError names the file and what is wrong.
TriangleMesh readStl(const std::string& path);

// The faces of `solid` that share an edge with face `face` (1-based numbers), the face itself first.
std::vector<int> faceAndNeighbours(const TopoDS_Shape& solid, int face);

}  // namespace hsm::geometry
