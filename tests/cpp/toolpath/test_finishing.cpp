// Finishing toolpaths on the master bottom feature and on slanted valleys, checked by an independent measure:
// the height map of the ball swept along the G1 moves, against the face itself (no generator number reused).
#include "common/error.hpp"
#include "curvenet/curvenet.hpp"
#include "geometry/face_drop.hpp"
#include "support/master_feature.hpp"
#include "support/surfaces.hpp"
#include "toolpath/finishing.hpp"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <Bnd_Box.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace hsm;
using namespace hsm::toolpath;

namespace {
constexpr auto feature = test::masterFeature;  // loaded once per program

int bottomIndex() {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(feature().shape, TopAbs_FACE, faces);
  return faces.FindIndex(feature().bottom);
}

struct Residual {
  double worstGouge = 0.0;  // mm the swept ball goes below the face
  double worstCusp = 0.0;   // mm of material left, measured along the face normal
  long samples = 0;
};

// The lowest point of the ball swept along the feed moves, above each point of a grid on the face, in the
// window [x0, x1] × [y0, y1]; compared with the face's own height there.
Residual sweep(const Toolpath& path, const TopoDS_Face& bottom, double r, double x0, double x1, double y0, double y1,
               double grid) {
  const int nx = int((x1 - x0) / grid) + 1, ny = int((y1 - y0) / grid) + 1;
  std::vector<double> envelope(static_cast<size_t>(nx) * ny, 1e300);
  for (size_t k = 1; k < path.moves.size(); ++k) {
    if (path.moves[k].rapid || path.moves[k - 1].rapid) continue;
    const Eigen::Vector3d a = path.moves[k - 1].point, b = path.moves[k].point;
    if (std::max(a.x(), b.x()) < x0 - r || std::min(a.x(), b.x()) > x1 + r || std::max(a.y(), b.y()) < y0 - r ||
        std::min(a.y(), b.y()) > y1 + r)
      continue;  // nowhere near the window
    const int steps = std::max(1, int(std::ceil((b - a).norm() / (0.4 * grid))));
    for (int s = 0; s <= steps; ++s) {
      const Eigen::Vector3d tip = a + (b - a) * double(s) / steps;
      const Eigen::Vector3d centre = tip + Eigen::Vector3d(0, 0, r);
      const int i0 = std::max(0, int(std::floor((centre.x() - r - x0) / grid)));
      const int i1 = std::min(nx - 1, int(std::ceil((centre.x() + r - x0) / grid)));
      const int j0 = std::max(0, int(std::floor((centre.y() - r - y0) / grid)));
      const int j1 = std::min(ny - 1, int(std::ceil((centre.y() + r - y0) / grid)));
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const double dx = x0 + i * grid - centre.x(), dy = y0 + j * grid - centre.y();
          const double d2 = dx * dx + dy * dy;
          if (d2 > r * r) continue;
          double& e = envelope[static_cast<size_t>(j) * nx + i];
          e = std::min(e, centre.z() - std::sqrt(r * r - d2));
        }
    }
  }
  const geometry::FaceDropper face(bottom, Eigen::Vector3d::UnitZ());
  Residual result;
  double u = 0, v = 0;
  bool guess = false;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      Eigen::RowVector3d p(x0 + i * grid, y0 + j * grid, 0.0);
      if (!face.dropOne(p, u, v, guess)) continue;
      guess = true;
      const double e = envelope[static_cast<size_t>(j) * nx + i];
      if (e > 1e299 || !face.inside(u, v)) continue;
      gp_Pnt point;
      gp_Vec su, sv;
      face.surface()->D1(u, v, point, su, sv);
      const gp_Vec n = su.Crossed(sv).Normalized();
      const double residual = (e - p.z()) * std::abs(n.Z());  // vertical → along the normal
      result.worstGouge = std::max(result.worstGouge, -residual);
      result.worstCusp = std::max(result.worstCusp, residual);
      ++result.samples;
    }
  return result;
}

FinishingSettings settings() {
  FinishingSettings s;
  s.toolRadius = 2.0;
  s.cuspHeight = 0.01;
  s.tolerance = 0.01;
  return s;
}
}  // namespace

// The material left is the cusp between passes plus the chords' deviation from the ideal path (within
// the machining tolerance): with a tight tolerance it is the cusp alone; with the usual one, at most both.
// The swept-ball grid (0.025 mm) and the sampling of the sweep add up to 0.001 mm.
void expectCuspAndNoGouge(const std::function<Toolpath(const FinishingSettings&)>& strategy, const char* name) {
  const std::array<double, 4> windows[] = {{64, 70, 12, 34}, {45, 55, 20, 28}};  // across the valley; the bump
  FinishingSettings tight = settings();
  tight.tolerance = 0.001;
  const Toolpath ideal = strategy(tight), usual = strategy(settings());
  EXPECT_GT(usual.passes, 80) << name;
  for (const auto& [x0, x1, y0, y1] : windows) {
    const Residual cusp = sweep(ideal, feature().bottom, 2.0, x0, x1, y0, y1, 0.025);
    EXPECT_GT(cusp.samples, 50000);
    EXPECT_LE(cusp.worstCusp, 0.011) << name << ": cusp between passes, window at " << x0 << ", " << y0;
    EXPECT_LE(cusp.worstGouge, 0.001) << name;
    const Residual real = sweep(usual, feature().bottom, 2.0, x0, x1, y0, y1, 0.025);
    EXPECT_LE(real.worstCusp, 0.01 + 0.01 + 0.001) << name << ": cusp and chords";
    EXPECT_LE(real.worstGouge, 0.01) << name << ": chords within the tolerance";
  }
}

TEST(Finishing, GuideCurvesKeepTheCuspAndNeverGouge) {
  expectCuspAndNoGouge(
      [](const FinishingSettings& s) {
        return guideCurveFinishing(feature().shape, bottomIndex(), {{feature().boundary1, feature().boundary2}},
                                   Eigen::Vector3d::UnitX(), s);
      },
      "guide curves");
}

TEST(Finishing, ParallelPlanesKeepTheCuspAndNeverGouge) {
  for (double angle : {0.0, 30.0})
    expectCuspAndNoGouge([angle](const FinishingSettings& s) {
      return parallelPlaneFinishing(feature().shape, bottomIndex(), angle, s);
    }, angle == 0.0 ? "planes at 0°" : "planes at 30°");
}

TEST(Finishing, PassesAcrossSlantedValleysKeepTheCuspWithoutCrowding) {
  // Valleys at 45° on 40 × 40 mm: passes along X cross them at a slant, so the contact of a station slides
  // along the pass from one pass to the next. Concave radius 18²/(2π²·3) = 5.5 mm at the bottoms.
  const TopoDS_Face face = test::slantedValleys(40.0, 3.0, 18.0, 33);
  FinishingSettings s = settings();
  s.tolerance = 0.001;
  const Toolpath path = parallelPlaneFinishing(face, 1, 0.0, s);
  const Residual cusp = sweep(path, face, 2.0, 17, 23, 17, 23, 0.025);
  EXPECT_GT(cusp.samples, 50000);
  EXPECT_LE(cusp.worstCusp, 0.011);
  EXPECT_LE(cusp.worstGouge, 0.001);
  // The cusp is set by where the passes' tubes meet, not by how far a station's contact slides along the
  // pass: where it is worst (the valley bottoms, seen at 45°: a concave section of radius R = 2·ρ) the
  // passes may be d = √(8·r·h·(1 − r/R)) apart; no more passes than that over the 40 mm, give or take the
  // edges, and the cusp left is the one asked for, not far less.
  const double rho = 18.0 * 18.0 / (2.0 * M_PI * M_PI * 3.0), r = 2.0, h = 0.01;
  const double bottomStep = std::sqrt(8.0 * r * h * (1.0 - r / (2.0 * rho)));
  const double flat = 2.0 * std::sqrt(2.0 * r * h - h * h);
  EXPECT_LE(path.passes, 1.1 * 40.0 / bottomStep + 4) << "passes crowd where the contacts slide";
  EXPECT_GE(cusp.worstCusp, 0.009) << "the passes are closer than the cusp needs";
  EXPECT_GE(path.passes, 40.0 / flat - 4) << "fewer passes than on a flat face";
}

TEST(Finishing, MovesStartAndEndAtTheSafeHeightAndRapidsStayAbove) {
  FinishingSettings s = settings();
  s.zigzag = false;
  const Toolpath path = parallelPlaneFinishing(feature().shape, bottomIndex(), 0.0, s);
  ASSERT_FALSE(path.moves.empty());
  EXPECT_TRUE(path.moves.front().rapid);
  EXPECT_DOUBLE_EQ(path.moves.front().point.z(), path.safeHeight);
  EXPECT_DOUBLE_EQ(path.moves.back().point.z(), path.safeHeight);
  for (size_t k = 1; k < path.moves.size(); ++k) {
    const bool horizontalRapid = path.moves[k].rapid && path.moves[k - 1].rapid &&
                                 path.moves[k].point.head<2>() != path.moves[k - 1].point.head<2>();
    if (horizontalRapid) {
      EXPECT_DOUBLE_EQ(path.moves[k].point.z(), path.safeHeight);  // at the safe height
    }
  }
  // One-way: every pass runs the same way along X.
  int forward = 0, backward = 0;
  for (size_t k = 1; k < path.moves.size(); ++k)
    if (!path.moves[k].rapid && !path.moves[k - 1].rapid) {
      const double dx = path.moves[k].point.x() - path.moves[k - 1].point.x();
      (dx > 0 ? forward : backward) += std::abs(dx) > 0.5;
    }
  EXPECT_TRUE(forward == 0 || backward == 0) << forward << " " << backward;
}

TEST(Finishing, ComposedAreasCutTheSharedGuideOnceAndSweepUpward) {
  curvenet::GuidanceSettings g;
  g.net.face = feature().bottom;
  const auto net = curvenet::guidanceCurves({feature().boundary1, feature().boundary2}, g).net;
  std::vector<GuideArea> areas;
  for (const auto& a : net.elementaryAreas()) areas.push_back({net.curves[a.lower].curve, net.curves[a.upper].curve});
  FinishingSettings s = settings();
  const Toolpath composed = guideCurveFinishing(feature().shape, bottomIndex(), areas, Eigen::Vector3d::UnitX(), s);
  const Toolpath single = guideCurveFinishing(feature().shape, bottomIndex(), {{feature().boundary1, feature().boundary2}},
                                              Eigen::Vector3d::UnitX(), s);
  EXPECT_GT(composed.passes, single.passes * 0.8);
  EXPECT_LT(composed.passes, single.passes * 1.6);
  s.sweep = Sweep::Downward;
  const Toolpath down = guideCurveFinishing(feature().shape, bottomIndex(), areas, Eigen::Vector3d::UnitX(), s);
  // The first feed move of the upward path is lower than the first of the downward one.
  auto firstFeed = [](const Toolpath& p) {
    for (const Move& m : p.moves)
      if (!m.rapid) return m.point;
    return Eigen::Vector3d(0, 0, 0);
  };
  EXPECT_NE(firstFeed(composed).y() > 30, firstFeed(down).y() > 30);  // they start on opposite sides
}

TEST(Finishing, BadSettingsAreRefused) {
  FinishingSettings s = settings();
  s.cuspHeight = 0.0;
  EXPECT_THROW(parallelPlaneFinishing(feature().shape, bottomIndex(), 0.0, s), hsm::InputError);
  s = settings();
  s.toolRadius = -1;
  EXPECT_THROW(parallelPlaneFinishing(feature().shape, bottomIndex(), 0.0, s), hsm::InputError);
  EXPECT_THROW(parallelPlaneFinishing(feature().shape, 99, 0.0, settings()), hsm::InputError);
  EXPECT_THROW(guideCurveFinishing(feature().shape, bottomIndex(), {}, Eigen::Vector3d::UnitX(), settings()), hsm::InputError);
  EXPECT_THROW(guideCurveFinishing(feature().shape, bottomIndex(), {{feature().boundary1, feature().boundary2}},
                                   Eigen::Vector3d::UnitZ(), settings()),
               hsm::InputError);
}

namespace {
// The top face (z = top) of a shape: the plane face whose normal is +Z at that height.
int topFaceIndex(const TopoDS_Shape& shape, double top) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    Bnd_Box box;
    BRepBndLib::Add(faces(i), box);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    if (std::abs(z0 - top) < 1e-6 && std::abs(z1 - top) < 1e-6 && x1 - x0 > 1.0 && y1 - y0 > 1.0) return i;
  }
  return 0;
}

// Points every `step` mm along the feed moves.
std::vector<Eigen::Vector3d> feedSamples(const Toolpath& path, double step) {
  std::vector<Eigen::Vector3d> samples;
  for (size_t k = 1; k < path.moves.size(); ++k) {
    if (path.moves[k].rapid || path.moves[k - 1].rapid) continue;
    const Eigen::Vector3d a = path.moves[k - 1].point, b = path.moves[k].point;
    const int n = std::max(1, int(std::ceil((b - a).norm() / step)));
    for (int s = 0; s <= n; ++s) samples.push_back(a + (b - a) * double(s) / n);
  }
  return samples;
}
}  // namespace

TEST(Finishing, AHoleInTheFaceIsBridgedAtItsLevelWithoutADip) {
  // A 30 × 20 × 5 mm plate with a 6 mm through hole: the ball (Ø4) must cross the hole at the face's level.
  const TopoDS_Shape plate = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(30, 20, 5).Shape(),
                                             BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(15, 10, 0), gp::DZ()), 3, 5).Shape())
                                 .Shape();
  const int top = topFaceIndex(plate, 5.0);
  ASSERT_GT(top, 0);
  FinishingSettings s = settings();
  s.tolerance = 0.001;
  const Toolpath path = parallelPlaneFinishing(plate, top, 0.0, s);
  double lowestOverHole = 1e300;
  long overHole = 0;
  for (const Eigen::Vector3d& p : feedSamples(path, 0.05))
    if (std::hypot(p.x() - 15.0, p.y() - 10.0) < 2.95) {
      lowestOverHole = std::min(lowestOverHole, p.z());
      ++overHole;
    }
  EXPECT_GT(overHole, 100) << "the passes should cross the hole";
  EXPECT_GE(lowestOverHole, 5.0 - 0.011) << "the ball dips into the hole";
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(plate, TopAbs_FACE, faces);
  const Residual residual = sweep(path, TopoDS::Face(faces(top)), 2.0, 4, 26, 3, 17, 0.025);
  EXPECT_GT(residual.samples, 100000);
  EXPECT_LE(residual.worstCusp, 0.011);
  EXPECT_LE(residual.worstGouge, 0.001);
}

TEST(Finishing, AFloorUnderAnOverhangIsNotReachedThroughThePart) {
  // A floor (z = 10) with a shelf over part of it (y 25..40 at z 20..25, on a wall at y 35..40): the ball
  // must stop where the shelf holds it up. With only the floor's neighbours meshed it fell through the shelf.
  const TopoDS_Shape base = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(60, 40, 10)).Shape();
  const TopoDS_Shape wall = BRepPrimAPI_MakeBox(gp_Pnt(0, 35, 10), gp_Pnt(60, 40, 20)).Shape();
  const TopoDS_Shape shelf = BRepPrimAPI_MakeBox(gp_Pnt(0, 25, 20), gp_Pnt(60, 40, 25)).Shape();
  BRepAlgoAPI_Fuse fused(BRepAlgoAPI_Fuse(base, wall).Shape(), shelf);
  ShapeUpgrade_UnifySameDomain unify(fused.Shape());
  unify.Build();
  const TopoDS_Shape part = unify.Shape();
  const int floor = topFaceIndex(part, 10.0);
  ASSERT_GT(floor, 0);
  FinishingSettings s = settings();
  s.cuspHeight = 0.05;
  const Toolpath path = parallelPlaneFinishing(part, floor, 0.0, s);
  ASSERT_GT(path.passes, 5);
  // Independent of the generator: the ball's centre keeps a radius from the solid (OCCT's distance).
  BRepClass3d_SolidClassifier inside(part);
  double closest = 1e300;
  for (const Eigen::Vector3d& tip : feedSamples(path, 0.5)) {
    const gp_Pnt centre(tip.x(), tip.y(), tip.z() + 2.0);
    inside.Perform(centre, 1e-7);
    ASSERT_NE(inside.State(), TopAbs_IN) << "the ball's centre is inside the part at " << tip.transpose();
    BRepExtrema_DistShapeShape distance(BRepBuilderAPI_MakeVertex(centre).Vertex(), part);
    closest = std::min(closest, distance.Value());
  }
  EXPECT_GE(closest, 2.0 - 0.011) << "the ball cuts into the part";
  for (const Move& m : path.moves) {
    if (!m.rapid && m.point.z() < 10.5) {
      EXPECT_LT(m.point.y(), 25.0 - 1.99) << "a pass on the floor under the shelf";
    }
  }
}

// Passes are cut side by side on the threads asked for (each pass's drop then single-threaded): the path is
// the one thread's, move for move, and a cancel from the progress callback stops every thread.
TEST(Finishing, PassesCutOnTwoThreadsAreOneThreadsAndCancelStopsThemAll) {
  FinishingSettings one = settings(), two = settings();
  one.threads = 1;
  two.threads = 2;
  const auto guide = [](const FinishingSettings& s) {
    return guideCurveFinishing(feature().shape, bottomIndex(), {{feature().boundary1, feature().boundary2}},
                               Eigen::Vector3d::UnitX(), s);
  };
  const Toolpath serial = guide(one), parallel = guide(two);
  ASSERT_EQ(serial.moves.size(), parallel.moves.size());
  for (size_t k = 0; k < serial.moves.size(); ++k) ASSERT_EQ(serial.moves[k].point, parallel.moves[k].point) << k;
  EXPECT_EQ(serial.passLengths, parallel.passLengths);
  EXPECT_EQ(serial.droppedPoints, parallel.droppedPoints);
  // Cancelled at the first report: the threads stop at their next pass. (A cancel asked late may find every
  // pass done before the calling thread looks again: the last progress, 1, is then reported and cancelled.)
  double last = 0.0;
  int reports = 0;
  two.progress = [&](double done) {
    last = done, ++reports;
    return false;
  };
  EXPECT_THROW(guide(two), Cancelled);
  EXPECT_EQ(reports, 1);
  EXPECT_GT(last, 0.0);
  EXPECT_LT(last, 1.0);
}
