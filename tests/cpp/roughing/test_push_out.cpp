// The push-out of a level's boundary to the cutter's real clearance: how far it goes beside a wall, that the
// clearance check (on its own finer mesh) agrees, the floor the level stands the allowance over, bad settings.
#include "common/error.hpp"
#include "geometry/mesh.hpp"
#include "roughing/clearance.hpp"
#include "roughing/flat.hpp"
#include "roughing/push_out.hpp"

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

using namespace hsm;
using namespace hsm::roughing;

namespace {
constexpr double kTip = 10.0;  // mm: the level's tip height

// Planes normal to Z, the tool pointing up (S1's projection of a slice whose reference face looks down).
std::unique_ptr<Projection> planesAlongZ() {
  Partition partition;
  partition.strategy = Strategy::PlanesParallelToFace;
  SubVolume sub;
  sub.surface.kind = SurfaceKind::Plane;
  sub.surface.direction = -Eigen::Vector3d::UnitZ();
  partition.subVolumes.push_back(sub);
  return projectionOf(partition, RemovalSolid{});
}

// A rectangle of the level, its corners given in the part's x and y, laid flat (anticlockwise).
cl::Path rectangle(const Projection& projection, double x0, double y0, double x1, double y1) {
  auto p = [&](double x, double y) { return projection.plane(Eigen::Vector3d(x, y, kTip)); };
  cl::Path path{p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)};
  if (!cl::Orientation(path)) cl::ReversePath(path);
  return path;
}

// The least x, in the part's frame, of the paths' points at the level.
double leastX(const cl::Paths& paths, const Projection& projection) {
  double least = std::numeric_limits<double>::infinity();
  for (const cl::Path& path : paths)
    for (const cl::IntPoint& q : path) least = std::min(least, projection.point(q, kTip).x());
  return least;
}

// The tool at every point of the paths' boundaries, its tip at the level.
std::vector<ToolMove> toolAt(const cl::Paths& paths, const Projection& projection) {
  std::vector<ToolMove> moves;
  for (const cl::Path& path : paths)
    for (const cl::IntPoint& q : path) moves.push_back({MoveKind::Cut, projection.point(q, kTip), Eigen::Vector3d::UnitZ(), 0});
  return moves;
}

// A block whose wall faces +X at x = 20, 30 mm high; with `floor`, a slab under the level, its top `floor` mm.
TopoDS_Shape wallBlock(double floor = -1.0) {
  TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, -30, 0), gp_Pnt(20, 30, 30)).Shape();
  if (floor > 0.0) block = BRepAlgoAPI_Fuse(block, BRepPrimAPI_MakeBox(gp_Pnt(0, -30, 0), gp_Pnt(60, 30, floor)).Shape()).Shape();
  return block;
}

PushSettings wallSettings() {
  PushSettings settings;
  settings.clearance = 0.55;
  settings.lowest = -0.495;  // the allowance, less the slack the sweep gives a floor
  settings.most = 3.0;
  return settings;
}
}  // namespace

// A domain held 7 mm from the wall (a Ø8 tool needs 4 + 0.55) comes to the clearance, within the push's step,
// and the independent check on a finer mesh finds the tool that far from the part; the sides that are the
// slice's own stay where they were.
TEST(PushOut, MovesABoundaryToTheClearanceBesideAWall) {
  const auto projection = planesAlongZ();
  const PartTriangles part(geometry::meshFacesAfresh(wallBlock(), 0.01));
  const Cutter cutter;
  const cl::Paths domain{rectangle(*projection, 27, -20, 60, 20)}, within{rectangle(*projection, 15, -20, 60, 20)};
  const cl::Paths pushed = pushedOut(domain, within, kTip, *projection, part, cutter, wallSettings());
  EXPECT_NEAR(leastX(pushed, *projection), 20.0 + 4.0 + 0.55, 0.06);
  EXPECT_GE(leastX(pushed, *projection), 24.55 - 1e-6) << "never nearer than the clearance";
  EXPECT_NEAR(area(pushed), area(domain) + 40.0 * (27.0 - 24.55), 40.0 * 0.06);
  EXPECT_NEAR(area(boolean(cl::ctDifference, pushed, within)), 0.0, 1e-6) << "within the slice";
  const ClearanceReport report = checkClearance(toolAt(pushed, *projection), wallBlock(), cutter, 0.54, 0.1, 0.005);
  EXPECT_EQ(report.tooClose, 0) << "closest " << report.minimum;
  EXPECT_LT(report.minimum, 0.62);
}

// A floor 0.5 mm under the tip (the allowance the level stands over) does not hold the push back; counted as
// part (no height left out), it holds every point where it is, 0.5 mm from the tool's bottom.
TEST(PushOut, LeavesOutTheFloorTheLevelStandsOver) {
  const auto projection = planesAlongZ();
  const PartTriangles part(geometry::meshFacesAfresh(wallBlock(kTip - 0.5), 0.01));
  const Cutter cutter;
  const cl::Paths domain{rectangle(*projection, 27, -20, 60, 20)}, within{rectangle(*projection, 15, -20, 60, 20)};
  EXPECT_NEAR(leastX(pushedOut(domain, within, kTip, *projection, part, cutter, wallSettings()), *projection), 24.55, 0.06);
  PushSettings everything = wallSettings();
  everything.lowest = -std::numeric_limits<double>::infinity();
  EXPECT_NEAR(area(pushedOut(domain, within, kTip, *projection, part, cutter, everything)), area(domain), 1e-6);
}

TEST(PushOut, BadSettingsAreRefusedByName) {
  const auto projection = planesAlongZ();
  const PartTriangles part(geometry::meshFacesAfresh(wallBlock(), 0.05));
  const cl::Paths domain{rectangle(*projection, 27, -20, 60, 20)};
  auto with = [&](auto change) {
    PushSettings settings = wallSettings();
    change(settings);
    try {
      pushedOut(domain, domain, kTip, *projection, part, Cutter{}, settings);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(with([](PushSettings& s) { s.most = 0.0; }).find("farthest move"), std::string::npos);
  EXPECT_NE(with([](PushSettings& s) { s.most = 50.0; }).find("farthest move"), std::string::npos);
  EXPECT_NE(with([](PushSettings& s) { s.spacing = 0.001; }).find("spacing"), std::string::npos);
  EXPECT_NE(with([](PushSettings& s) { s.clearance = -1.0; }).find("clearance"), std::string::npos);
  EXPECT_NE(with([](PushSettings& s) { s.clearance = std::numeric_limits<double>::quiet_NaN(); }).find("clearance"),
            std::string::npos);
  EXPECT_TRUE(pushedOut({}, domain, kTip, *projection, part, Cutter{}, wallSettings()).empty());
}
