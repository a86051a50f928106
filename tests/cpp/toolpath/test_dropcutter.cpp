#include "common/error.hpp"
#include "toolpath/dropcutter.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <gp_Pln.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <Bnd_Box.hxx>
#include <gtest/gtest.h>

#include <cmath>

using namespace hsm;
using namespace hsm::geometry;
using namespace hsm::toolpath;

namespace {
TriangleMesh singleTriangle(Eigen::Vector3d a, Eigen::Vector3d b, Eigen::Vector3d c) {
  TriangleMesh mesh;
  mesh.vertices = {a, b, c};
  mesh.triangles = {Eigen::Vector3i(0, 1, 2)};
  mesh.faceOf = {7};
  return mesh;
}
}  // namespace

TEST(DropCutter, FacetOfATiltedPlane) {
  // Plane z = 0.5 x: the ball touches it off-centre; tip z = plane z at (x, y) + r (1/cos - 1)·… in closed form.
  const TriangleMesh mesh = singleTriangle({-50, -50, -25}, {50, -50, 25}, {0, 50, 0});
  const double r = 2.0;
  const BallDropCutter cutter(mesh, r);
  const double slope = 0.5, cosine = 1.0 / std::sqrt(1 + slope * slope);
  const Contact c = cutter.drop(1.0, 0.0);
  EXPECT_NEAR(c.z, slope * 1.0 + r / cosine - r, 1e-12);  // centre is r/cos above the plane
  EXPECT_EQ(c.face, 7);
  EXPECT_FALSE(cutter.drop(500, 0).touches());
}

TEST(DropCutter, VertexAndEdgeContacts) {
  const double r = 3.0;
  // A flat triangle below z = 0 and a spike vertex at z = 1: near the spike the vertex lifts the tool.
  const TriangleMesh spike = singleTriangle({0, 0, 1}, {-10, 40, -5}, {-40, -10, -5});
  const BallDropCutter cutter(spike, r);
  EXPECT_NEAR(cutter.drop(1.0, 0.0).z, 1.0 + std::sqrt(r * r - 1.0) - r, 1e-12);
  // A roof ridge along X at z = 2 (two faces): over the ridge the edge holds the ball.
  TriangleMesh roof;
  roof.vertices = {{-20, 0, 2}, {20, 0, 2}, {20, 10, 0}, {-20, 10, 0}, {20, -10, 0}, {-20, -10, 0}};
  roof.triangles = {Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 3), Eigen::Vector3i(0, 4, 1),
                    Eigen::Vector3i(0, 5, 4)};
  const BallDropCutter ridge(roof, r);
  EXPECT_NEAR(ridge.drop(3.0, 0.0).z, 2.0, 1e-12);  // centre r above the ridge
  const double y = 0.3;                              // still on the edge: centre at distance r from it
  EXPECT_NEAR(ridge.drop(3.0, y).z, 2.0 + std::sqrt(r * r - y * y) - r, 1e-12);
}

TEST(DropCutter, CylinderMatchesTheAnalyticOffset) {
  // A horizontal cylinder of radius 20 along X, top at z = 0: tip z = sqrt((R+r)² − y²) − R − r.
  const double R = 20.0, r = 2.0;
  const TopoDS_Shape cylinder =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-30, 0, -R), gp::DX()), R, 60.0).Shape();
  const BallDropCutter cutter(meshFaces(cylinder, 1e-4), r);
  for (double y : {0.0, 3.0, 7.5, 12.0}) EXPECT_NEAR(cutter.drop(0.0, y).z, std::sqrt((R + r) * (R + r) - y * y) - R - r, 2e-4) << y;
}

TEST(DropCutter, ManyPointsOnTwoThreadsEqualOneByOne) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, -10), 50, 30, 10).Shape();
  const BallDropCutter cutter(meshFaces(box, 0.01), 2.0);
  geometry::PointArray points(10000, 3);
  for (int i = 0; i < points.rows(); ++i) points.row(i) << -5 + 60.0 * i / points.rows(), 15.0 + std::sin(i), 0;
  geometry::PointArray parallel = points;
  std::vector<int> faces;
  cutter.dropAll(parallel, &faces, 2);
  for (int i = 0; i < points.rows(); i += 97) {
    const Contact c = cutter.drop(points(i, 0), points(i, 1));
    EXPECT_EQ(parallel(i, 2), c.z);
    EXPECT_EQ(faces[static_cast<size_t>(i)], c.face);
  }
  EXPECT_NEAR(parallel(5000, 2), 0.0, 1e-12);  // on the top face
}

namespace {
bool sameMesh(const TriangleMesh& a, const TriangleMesh& b) {
  return a.vertices == b.vertices && a.triangles == b.triangles && a.faceOf == b.faceOf;
}
}  // namespace

TEST(DropCutter, KeptMeshesAreTheMeshesOfTheSameFacesInTheSameState) {
  // A fresh copy of the same part (as a BREP read again gives): the kept mesh, equal to meshing it; another
  // deflection, other faces or another part are meshed for themselves.
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 20.0, 30.0).Shape();
  const auto fresh = [&] { return BRepBuilderAPI_Copy(cylinder, Standard_True, Standard_False).Shape(); };
  const TriangleMesh first = meshFacesKept(fresh(), 0.05, {1, 2});
  EXPECT_TRUE(sameMesh(first, meshFaces(fresh(), 0.05, {1, 2})));
  EXPECT_TRUE(sameMesh(meshFacesKept(fresh(), 0.05, {1, 2}), first));
  const TriangleMesh finer = meshFacesKept(fresh(), 0.01, {1, 2});
  EXPECT_GT(finer.triangles.size(), first.triangles.size());
  EXPECT_TRUE(sameMesh(finer, meshFaces(fresh(), 0.01, {1, 2})));
  EXPECT_TRUE(sameMesh(meshFacesKept(fresh(), 0.05, {2}), meshFaces(fresh(), 0.05, {2})));
  const TopoDS_Shape wider = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 21.0, 30.0).Shape();
  EXPECT_TRUE(sameMesh(meshFacesKept(wider, 0.05, {1, 2}), meshFaces(BRepBuilderAPI_Copy(wider).Shape(), 0.05, {1, 2})));
  EXPECT_THROW(meshFacesKept(fresh(), 0.05, {9}), InputError);
  // What runs after reads the triangulations meshing leaves on the faces (a bounding box of the part): a hit
  // leaves the same ones.
  const auto boxAfter = [&](const TopoDS_Shape& part) {
    meshFacesKept(part, 0.05, {1});
    Bnd_Box box;
    BRepBndLib::Add(part, box);
    return box.CornerMax().X();  // from the lateral face's triangulation, or from its geometry
  };
  const TopoDS_Shape missed = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 20.0, 31.0).Shape();
  const double side = boxAfter(missed);
  Bnd_Box untouched;
  BRepBndLib::Add(BRepBuilderAPI_Copy(missed, Standard_True, Standard_False).Shape(), untouched);
  EXPECT_NE(side, untouched.CornerMax().X()) << "the box is the triangulation's where there is one";
  EXPECT_EQ(boxAfter(BRepBuilderAPI_Copy(missed, Standard_True, Standard_False).Shape()), side);
}

TEST(DropCutter, BadInput) {
  EXPECT_THROW(BallDropCutter(TriangleMesh{}, 2.0), InputError);
  EXPECT_THROW(BallDropCutter(singleTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), 0.0), InputError);
  EXPECT_THROW(readStl("/nonexistent.stl"), InputError);
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(1, 1, 1).Shape();
  EXPECT_THROW(meshFaces(box, 0.01, {7}), InputError);
  EXPECT_EQ(faceAndNeighbours(box, 1).size(), 5u);  // a box face touches four others
}
