#include "common/error.hpp"
#include "geometry/brep.hpp"
#include "geometry/mesh.hpp"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <gtest/gtest.h>

#include <cmath>

using namespace hsm::geometry;

TEST(Brep, BoxSurvivesRoundTripWithItsTopologyAndMeasures) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10.0, 20.0, 30.0).Shape();
  const ShapeSummary s = summarize(readBrep(writeBrep(box)));
  EXPECT_EQ(s.solids, 1);
  EXPECT_EQ(s.faces, 6);
  EXPECT_EQ(s.edges, 12);
  EXPECT_EQ(s.vertices, 8);
  EXPECT_NEAR(s.volume, 6000.0, 1e-6);
  EXPECT_NEAR(s.area, 2 * (200.0 + 300.0 + 600.0), 1e-6);
  EXPECT_NEAR(s.length, 4 * (10.0 + 20.0 + 30.0), 1e-6);
  EXPECT_TRUE(s.valid);
  EXPECT_NEAR(s.bounds.max().z(), 30.0, 1e-6);
  EXPECT_NEAR(s.bounds.min().x(), 0.0, 1e-6);
}

TEST(Brep, BooleanResultKeepsExactVolume) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(40.0, 40.0, 10.0).Shape();
  const TopoDS_Shape hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 20, -1), gp::DZ()), 5.0, 12.0).Shape();
  const TopoDS_Shape part = BRepAlgoAPI_Cut(box, hole).Shape();
  const ShapeSummary s = summarize(readBrep(writeBrep(part)));
  EXPECT_NEAR(s.volume, 40.0 * 40.0 * 10.0 - M_PI * 25.0 * 10.0, 1e-3);
  EXPECT_EQ(s.faces, 7);
  EXPECT_TRUE(s.valid);
}

TEST(Brep, EmptyTextIsRefusedWithAMessageNamingTheInput) {
  try {
    readBrep("  \n");
    FAIL() << "empty BREP text was accepted";
  } catch (const hsm::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("BREP text is empty"), std::string::npos);
  }
}

TEST(Brep, GarbageTextIsRefused) {
  EXPECT_THROW(readBrep("this is not a shape"), hsm::InputError);
  EXPECT_THROW(readBrep("DBRep_DrawableShape\n\nCASCADE Topology V1, (c) Matra-Datavision\nLocations 3\n"),
               hsm::InputError);
}

TEST(Brep, NullShapeSummaryIsEmpty) {
  const ShapeSummary s = summarize(TopoDS_Shape());
  EXPECT_EQ(s.faces, 0);
  EXPECT_TRUE(s.bounds.isEmpty());
  EXPECT_FALSE(s.valid);
}

TEST(Brep, MalformedTextThatMadeOcctLoopForEverIsRefused) {
  // Found by fuzz_brep_curvenet: OCCT's reader kept reading from a failed stream, for ever (and growing).
  const std::string text =
      "\nCASCADE Topology V1, (c) Matra-Datavision\nLocations 0\nCurve2ds 0\nCurves 2\n1 0 0 0 1 0 0 \n"
      "1 0 20 0 0.99920095872178938 0.n039968038348871575 0 \nPolygon3D 0\n";
  EXPECT_THROW(hsm::geometry::readBrep(text), hsm::InputError);
}

// OCCT 7.9's mesher can run for ever on a malformed face: every mesh of the core is stopped at a time limit and
// refused with a message that says what to check. Here a fine mesh of a sphere, given no time at all.
TEST(Mesh, AMesherPastItsTimeLimitIsStoppedAndRefused) {
  const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(50.0).Shape();
  try {
    meshFaces(sphere, 0.001, {}, 1e-9);
    FAIL() << "a mesh with no time left was made";
  } catch (const hsm::ComputationError& error) {
    EXPECT_NE(std::string(error.what()).find("OCCT's mesher had not meshed the faces"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("Check geometry"), std::string::npos);
  }
  EXPECT_GT(meshFaces(BRepPrimAPI_MakeSphere(50.0).Shape(), 0.1).triangles.size(), 100u);  // in time: meshed
}
