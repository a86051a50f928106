// The partition on analytic reference faces (a ball, a dome) and the bounds of its work: estimated before the
// split and refused with the step that fits.
#include "common/error.hpp"
#include "common/progress.hpp"
#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>

using namespace hsm;
using namespace hsm::roughing;

namespace {

// Least and largest distance of a shape's mesh nodes from a point.
std::pair<double, double> radialSpan(const TopoDS_Shape& shape, const gp_Pnt& centre) {
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(shape).Shape();
  BRepMesh_IncrementalMesh(copy, 0.5, Standard_False, 0.5);  // nodes lie on the faces whatever the deflection
  double low = 1e300, high = -1e300;
  for (TopExp_Explorer it(copy, TopAbs_FACE); it.More(); it.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(TopoDS::Face(it.Current()), location);
    if (mesh.IsNull()) continue;
    for (int i = 1; i <= mesh->NbNodes(); ++i) {
      const double r = mesh->Node(i).Transformed(location.Transformation()).Distance(centre);
      low = std::min(low, r);
      high = std::max(high, r);
    }
  }
  return {low, high};
}

const RemovalSolid& ballInBox() {
  static const VolumeToRemove v = volumeToRemove(BRepPrimAPI_MakeBox(gp_Pnt(-50, -50, -50), 100, 100, 100).Shape(),
                                                 BRepPrimAPI_MakeSphere(20.0).Shape());
  return v.solids.front();
}

}  // namespace

// S5 about a ball held in a box: concentric spheres, each shell inside the box exactly 4/3 π (r₂³ − r₁³), the
// shells the box cuts in slices of their own (not given to slice 0 because their centre of mass is the ball's).
TEST(PartitionBounds, ConcentricSpheresSliceTheBoxAroundABall) {
  const Partition p = partition(ballInBox(), BRepPrimAPI_MakeSphere(20.0).Shape(), Strategy::HubOffsets, {2.0});
  const double cornerDistance = std::sqrt(3.0) * 50.0;
  ASSERT_EQ(p.subVolumes.size(), static_cast<size_t>(std::ceil((cornerDistance - 20.0) / 2.0)));
  for (size_t k = 0; k < p.subVolumes.size(); ++k) {
    const SubVolume& sub = p.subVolumes[k];
    EXPECT_EQ(sub.slice, static_cast<int>(k));
    EXPECT_EQ(sub.surface.kind, SurfaceKind::Revolution);
    const double r1 = 20.0 + 2.0 * k, r2 = r1 + 2.0;
    if (r2 <= 50.0) EXPECT_NEAR(sub.volume, 4.0 / 3.0 * M_PI * (r2 * r2 * r2 - r1 * r1 * r1), 1e-6 * sub.volume) << k;
    const auto [low, high] = radialSpan(sub.shape, gp_Pnt(0, 0, 0));
    EXPECT_GT(low, r1 - 0.02) << k;
    EXPECT_LT(high, std::min(r2, cornerDistance) + 0.02) << k;
    ASSERT_FALSE(sub.axisDirections.empty()) << k;
    // The tool axis points away from the ball (S5: away from the floor).
    const Eigen::Vector3d radial = sub.axisPoints.front().normalized();
    EXPECT_GT(sub.axisDirections.front().dot(radial), 0.999) << k;
  }
  EXPECT_NEAR(p.volume, ballInBox().volume, 1e-6 * p.volume);
}

// A dome on a plate, larger than the plate's top: S5 follows the dome by concentric spheres.
TEST(PartitionBounds, ADomeOnAPlateSlicesByConcentricSpheres) {
  BRepAlgoAPI_Fuse fuse(BRepPrimAPI_MakeBox(gp_Pnt(-50, -50, 0), 100, 100, 10).Shape(),
                        BRepPrimAPI_MakeSphere(gp_Ax2(gp_Pnt(0, 0, 10), gp::DZ()), 45.0, 0.0, M_PI / 2).Shape());
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape());
  unify.Build();
  const TopoDS_Shape part = unify.Shape();
  const VolumeToRemove v = volumeToRemove(BRepPrimAPI_MakeBox(gp_Pnt(-50, -50, 0), 100, 100, 70).Shape(), part);
  const Partition p = partition(v.solids.front(), part, Strategy::HubOffsets, {8.0});
  ASSERT_EQ(p.subVolumes.size(), 6u);  // the farthest corner is 92.7 mm from the centre: 47.7 mm of offsets
  for (const SubVolume& sub : p.subVolumes) {
    const auto [low, high] = radialSpan(sub.shape, gp_Pnt(0, 0, 10));
    EXPECT_GT(low, 45.0 + 8.0 * sub.slice - 0.02) << sub.slice;
    EXPECT_LT(high, 45.0 + 8.0 * (sub.slice + 1) + 0.02) << sub.slice;
  }
  EXPECT_NEAR(p.volume, v.volume, 1e-6 * v.volume);
}

// A step that makes too much work is refused before the split, naming the step that fits; that step passes
// the estimate (the computation then starts: cancelled at its first report after the estimate).
TEST(PartitionBounds, TooMuchWorkIsRefusedWithTheStepThatFits) {
  const PartAndStock wheel = impeller();
  const VolumeToRemove v = volumeToRemove(wheel.stock, wheel.part);
  const RemovalSolid& channel = v.solids.front();
  for (const auto& [strategy, step] : {std::pair{Strategy::CoaxialCylinders, 0.05}, {Strategy::StockOffsets, 0.1},
                                       {Strategy::HubOffsets, 0.1}}) {
    std::string message;
    try {
      partition(channel, wheel.part, strategy, {step});
    } catch (const InputError& e) {
      message = e.what();
    }
    std::smatch found;
    ASSERT_TRUE(std::regex_search(message, found, std::regex("use a step of at least ([0-9.]+) mm")))
        << strategyName(strategy) << ": " << message;
    EXPECT_NE(message.find("s of splitting"), std::string::npos) << message;
    const double fits = std::stod(found[1]);
    EXPECT_GT(fits, step) << message;
    EXPECT_LT(fits, 2.0) << message;
    PartitionSettings settings{fits};
    settings.progress = [](double done) { return done < 0.15; };
    EXPECT_THROW(partition(channel, wheel.part, strategy, settings), Cancelled) << strategyName(strategy) << " at " << fits;
  }
}
