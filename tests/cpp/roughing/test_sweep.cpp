#include "common/error.hpp"
#include "roughing/parts.hpp"
#include "roughing/roughing.hpp"
#include "roughing/clearance.hpp"
#include "roughing/removal.hpp"
#include "roughing/sweep.hpp"
#include "fixtures.hpp"

#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace hsm;
using namespace hsm::roughing;

namespace {
const fixtures::PartCase& slot() { return fixtures::wideSlot(); }

SweepResult sweepOf(Strategy strategy, const SweepSettings& settings = {}, Partition* kept = nullptr) {
  const fixtures::PartCase& c = slot();
  Partition partition = roughing::partition(c.volume.solids.front(), c.shapes.part, strategy);
  SweepResult result = sweep(partition, c.volume.solids.front(), c.shapes.part, c.shapes.stock, settings);
  if (kept) *kept = std::move(partition);
  return result;
}

double distanceToLoop(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& loop) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d& a = loop[i];
    const Eigen::Vector3d d = loop[(i + 1) % loop.size()] - a;
    const double t = d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * d - p).norm());
  }
  return best;
}

// Independent of the generator: OCCT's exact distance from the part to the torus tool, as the distance to its
// core (a cylinder of radius R − r standing r above the tip, over the stick-out) less its corner radius r.
double clearance(const TopoDS_Shape& part, const ToolMove& move, const Cutter& cutter) {
  const Eigen::Vector3d base = move.tip + cutter.corner() * move.axis.normalized();
  const gp_Ax2 axis(gp_Pnt(base.x(), base.y(), base.z()), gp_Dir(move.axis.x(), move.axis.y(), move.axis.z()));
  const TopoDS_Shape core =
      BRepPrimAPI_MakeCylinder(axis, cutter.radius() - cutter.corner(), cutter.stickOut - cutter.corner()).Shape();
  BRepExtrema_DistShapeShape distance(core, part);
  EXPECT_TRUE(distance.IsDone());
  BRepClass3d_SolidClassifier inside(part, axis.Location(), 1e-7);
  return inside.State() == TopAbs_IN ? -1.0 : distance.Value() - cutter.corner();
}
}  // namespace

TEST(Sweep, SlotPlanesKeepOneAxisTheEngagementAndTheAllowance) {
  Partition partition;
  const SweepSettings settings;
  const SweepResult r = sweepOf(Strategy::PlanesParallelToFace, settings, &partition);
  ASSERT_FALSE(r.passes.empty());
  ASSERT_FALSE(r.moves.empty());
  // S1: every tool axis is the same, normal to the slicing planes, out through the top face.
  for (const ToolMove& m : r.moves) EXPECT_GT(m.axis.dot(r.moves.front().axis), 1.0 - 1e-12);
  EXPECT_GT(r.moves.front().axis.dot(-partition.subVolumes.front().surface.direction), 1.0 - 1e-12);
  // Neighbouring passes of a slice's main level are as far apart as their rings' offsets say: the radial
  // engagement (0.7 × 8 = 5.6 mm), less for a ring between that keeps an island from being left.
  const double step = settings.radialEngagement * settings.cutter.diameter;
  int pairs = 0;
  for (const Pass& inner : r.passes) {
    if (inner.ring == 0 || inner.intermediate) continue;
    std::vector<const Pass*> outer;
    for (const Pass& p : r.passes)
      if (p.subVolume == inner.subVolume && p.ring == inner.ring - 1 && !p.intermediate) outer.push_back(&p);
    ASSERT_FALSE(outer.empty());
    const double apart = inner.depth - outer.front()->depth;
    EXPECT_LE(apart, step + 1e-9);
    for (const Eigen::Vector3d& q : inner.points) {
      double d = std::numeric_limits<double>::infinity();
      for (const Pass* p : outer) d = std::min(d, distanceToLoop(q, p->points));
      EXPECT_NEAR(d, apart, 0.05) << "sub-volume " << inner.subVolume << " ring " << inner.ring;
    }
    ++pairs;
  }
  EXPECT_GT(pairs, 0);
  // No tool position closer to the part than the allowance − 0.01 mm: every cut, ramp and link move, every
  // 5 mm along it.
  const TopoDS_Shape& part = slot().shapes.part;
  int checked = 0;
  double closest = std::numeric_limits<double>::infinity();
  for (size_t i = 1; i < r.moves.size(); ++i) {
    if (r.moves[i].kind == MoveKind::Rapid) continue;
    const Eigen::Vector3d from = r.moves[i - 1].tip, to = r.moves[i].tip;
    const int samples = 1 + static_cast<int>((to - from).norm() / 5.0);
    for (int k = 1; k <= samples; ++k) {
      ToolMove at = r.moves[i];
      at.tip = from + (to - from) * (double(k) / samples);
      closest = std::min(closest, clearance(part, at, settings.cutter));
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
  EXPECT_GE(closest, settings.allowance - 0.01);
  EXPECT_LT(closest, settings.allowance + 0.2) << "the passes go as close as the allowance lets them";
}

TEST(Sweep, EntriesRampIntoMaterialAndLinksRetractAlongTheAxis) {
  SweepSettings settings;
  const SweepResult r = sweepOf(Strategy::PlanesParallelToFace, settings);
  EXPECT_GT(r.ramps, 0);
  const double slope = std::tan(settings.rampAngleDeg * M_PI / 180.0);
  for (size_t i = 1; i < r.moves.size(); ++i) {
    const ToolMove& m = r.moves[i];
    const Eigen::Vector3d d = m.tip - r.moves[i - 1].tip;
    const double along = d.dot(m.axis), across = (d - along * m.axis).norm();
    if (m.kind == MoveKind::Ramp) {
      EXPECT_LE(-along, slope * across * 1.001 + 1e-5) << "move " << i;  // 0.1 µm: the plane's integers
    }
    if (m.kind == MoveKind::Cut) {
      EXPECT_NEAR(along, 0.0, 1e-9) << "move " << i;
    }
    if (m.kind == MoveKind::Link) {  // at a level, or from one level of a slice to another
      EXPECT_LE(std::abs(along), 8.0 + 1e-9) << "move " << i;
    }
  }
  // Every retract ends at one height above the stock, along the axis.
  double safe = -std::numeric_limits<double>::infinity();
  for (const ToolMove& m : r.moves) safe = std::max(safe, m.tip.dot(m.axis));
  EXPECT_GT(r.retracts, 0);
  EXPECT_NEAR(r.moves.back().tip.dot(r.moves.back().axis), safe, 1e-9);
  EXPECT_GT(r.cuttingLength, 0.0);
}

TEST(Sweep, SetupPlanesSweepAlongTheSetupDirection) {
  Partition partition;
  const SweepResult r = sweepOf(Strategy::SetupPlanes, {}, &partition);
  ASSERT_FALSE(r.moves.empty());
  for (const ToolMove& m : r.moves) EXPECT_GT(m.axis.dot(partition.setupDirection), 1.0 - 1e-9);
  int cuts = 0;
  for (const ToolMove& m : r.moves) cuts += m.kind == MoveKind::Cut;
  EXPECT_GT(cuts, 10);
}

TEST(Sweep, BadSettingsAreRefusedByName) {
  auto message = [](const SweepSettings& s, Strategy strategy = Strategy::PlanesParallelToFace) {
    try {
      sweepOf(strategy, s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  SweepSettings s;
  s.radialEngagement = 0.0;
  EXPECT_NE(message(s).find("radial engagement = 0 must be in [0.01, 1]"), std::string::npos);
  s = {};
  s.allowance = -1.0;
  EXPECT_NE(message(s).find("allowance = -1 is outside"), std::string::npos);
  s = {};
  s.cutter.cornerRadius = 4.0;
  EXPECT_NE(message(s).find("corner radius 4 mm must be in ]0, 4["), std::string::npos);
  s = {};
  s.cutter.fluteLength = 60.0;
  EXPECT_NE(message(s).find("longer than its stick-out"), std::string::npos);
}

TEST(Clearance, AgreesWithOcctAndFindsAGouge) {
  SweepSettings settings;
  const SweepResult r = sweepOf(Strategy::PlanesParallelToFace, settings);
  const TopoDS_Shape& part = slot().shapes.part;
  const ClearanceReport report = checkClearance(r.moves, part, settings.cutter, settings.allowance - 0.01, 1.0);
  EXPECT_EQ(report.tooClose, 0) << "worst move " << report.worstMove << " at " << report.minimum << " mm";
  EXPECT_GE(report.minimum, settings.allowance - 0.01);
  EXPECT_LT(report.minimum, settings.allowance + 0.2);
  EXPECT_GT(report.positions, 500);
  // The mesh check and OCCT's exact distance agree where the tool is near the part (cut moves, within 2 mm).
  int compared = 0;
  for (size_t i = 0; i < r.moves.size(); ++i) {
    if (r.moves[i].kind != MoveKind::Cut) continue;
    const ClearanceReport one = checkClearance({r.moves[i]}, part, settings.cutter, 0.0, 1.0);
    const double exact = clearance(part, r.moves[i], settings.cutter);
    if (exact > 2.0) continue;
    EXPECT_NEAR(one.minimum, exact, 0.02) << "move " << i;
    ++compared;
  }
  EXPECT_GT(compared, 5);
  // One millimetre across the slot (X): the passes along one wall cut into it, and the report says where.
  std::vector<ToolMove> lowered = r.moves;
  for (ToolMove& m : lowered) m.tip += Eigen::Vector3d::UnitX();
  const ClearanceReport gouge = checkClearance(lowered, part, settings.cutter, settings.allowance - 0.01, 1.0);
  EXPECT_GT(gouge.tooClose, 0);
  EXPECT_LT(gouge.minimum, 0.0) << "the tool is in the part";
  ASSERT_GE(gouge.worstMove, 0);
  EXPECT_NE(lowered[static_cast<size_t>(gouge.worstMove)].kind, MoveKind::Rapid);
  EXPECT_THROW(checkClearance(r.moves, part, settings.cutter, 0.49, 0.0), InputError);
}

TEST(Sweep, ImpellerCylindersKeepTheAxisRadialAndClearOfTheBlades) {
  // S2 on one channel of the impeller: coaxial cylinders about the outlet, a 4-axis path.
  const PartAndStock wheel = impeller();
  const VolumeToRemove volume = volumeToRemove(wheel.stock, wheel.part);
  const RemovalSolid& channel = volume.solids.front();
  const Partition partition = roughing::partition(channel, wheel.part, Strategy::CoaxialCylinders);
  const SweepSettings settings;
  const SweepResult r = sweep(partition, channel, wheel.part, wheel.stock, settings);
  ASSERT_FALSE(r.passes.empty());
  const Eigen::Vector3d origin = partition.subVolumes.front().surface.origin;
  const Eigen::Vector3d z = partition.subVolumes.front().surface.direction.normalized();
  int radial = 0;
  double spread = 0.0;
  for (const ToolMove& m : r.moves) {
    Eigen::Vector3d w = m.tip - origin;
    w -= z * z.dot(w);
    EXPECT_GE(m.axis.dot(w.normalized()), 0.9999);
    spread = std::max(spread, 1.0 - m.axis.dot(r.moves.front().axis));
    ++radial;
  }
  EXPECT_GT(radial, 50);
  EXPECT_GT(std::acos(1.0 - spread) * 180.0 / M_PI, 5.0) << "the axis turns about the cylinders' axis: a 4-axis path";
  // Every level's passes lie on its cylinder (cut moves at one radius per pass).
  for (const Pass& pass : r.passes) {
    double low = 1e300, high = -1e300;
    for (const Eigen::Vector3d& p : pass.points) {
      Eigen::Vector3d w = p - origin;
      w -= z * z.dot(w);
      low = std::min(low, w.norm());
      high = std::max(high, w.norm());
    }
    EXPECT_LT(high - low, 1e-6);
  }
  const ClearanceReport clear = checkClearance(r.moves, wheel.part, settings.cutter, settings.allowance - 0.01, 1.0);
  EXPECT_EQ(clear.tooClose, 0) << "closest " << clear.minimum << " mm at move " << clear.worstMove;
}


// S4 and S5 on a channel of the impeller: continuous 5-axis paths on offsets of the skin and of the hub.
// Checked independently of the sweep's meridian: OCCT projects every cut point on the reference surface (the
// face's own untrimmed surface): the point lies at the level's offset from it, the tool axis along the
// projection's line (normal to the offsets), and the tool clears the part (the mesh check).
class ImpellerOffsets : public ::testing::TestWithParam<Strategy> {};

TEST_P(ImpellerOffsets, AxesNormalToTheOffsetsAndClearOfTheBlades) {
  const fixtures::PartCase& c = fixtures::impellerCase();
  const RemovalSolid& channel = c.volume.solids.front();
  const Partition partition = roughing::partition(channel, c.shapes.part, GetParam());
  const SweepSettings settings;
  const SweepResult r = sweep(partition, channel, c.shapes.part, c.shapes.stock, settings);
  ASSERT_FALSE(r.passes.empty()) << strategyName(GetParam());
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(channel.solid, TopAbs_FACE, faces);
  const Handle(Geom_Surface) reference = BRep_Tool::Surface(TopoDS::Face(faces(partition.referenceFace)));
  double spread = 0.0;
  int checked = 0;
  for (const Pass& pass : r.passes) {
    double low = 1e300, high = -1e300;
    for (size_t k = 0; k < pass.points.size(); k += 7) {
      const Eigen::Vector3d& p = pass.points[k];
      GeomAPI_ProjectPointOnSurf foot(gp_Pnt(p.x(), p.y(), p.z()), reference);
      ASSERT_GT(foot.NbPoints(), 0);
      const gp_Pnt q = foot.NearestPoint();
      const Eigen::Vector3d towards = (p - Eigen::Vector3d(q.X(), q.Y(), q.Z())).normalized();
      low = std::min(low, foot.LowerDistance()), high = std::max(high, foot.LowerDistance());
      // The same tip's axis (the move ending there).
      for (const ToolMove& m : r.moves)
        if ((m.tip - p).norm() < 1e-9) {
          EXPECT_GE(std::abs(m.axis.dot(towards)), 0.9999) << "a tool axis off the offsets' normal";
          spread = std::max(spread, std::acos(std::clamp(m.axis.dot(r.moves.front().axis), -1.0, 1.0)));
          ++checked;
          break;
        }
    }
    EXPECT_LT(high - low, 0.02) << "a pass off its offset surface: " << low << " to " << high << " mm";
  }
  EXPECT_GT(checked, 20);
  EXPECT_GT(spread * 180.0 / M_PI, 20.0) << "the axis turns along the passes: a continuous 5-axis path";
  const ClearanceReport clear = checkClearance(r.moves, c.shapes.part, settings.cutter, settings.allowance - 0.01, 1.0);
  EXPECT_EQ(clear.tooClose, 0) << "closest " << clear.minimum << " mm at move " << clear.worstMove;
  // Neighbouring passes of a level never farther apart than the engagement asked (measured in space).
  const double step = settings.radialEngagement * settings.cutter.diameter;
  for (const Pass& inner : r.passes) {
    if (inner.ring == 0) continue;
    for (size_t k = 0; k < inner.points.size(); k += 5) {
      double d = std::numeric_limits<double>::infinity();
      for (const Pass& outer : r.passes)
        if (outer.subVolume == inner.subVolume && outer.ring == inner.ring - 1)
          d = std::min(d, distanceToLoop(inner.points[k], outer.points));
      EXPECT_LE(d, step + 0.05);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sweep, ImpellerOffsets, ::testing::Values(Strategy::StockOffsets, Strategy::HubOffsets),
                         [](const ::testing::TestParamInfo<Strategy>& info) {
                           return info.param == Strategy::StockOffsets ? std::string("S4") : std::string("S5");
                         });

// Two channels in one program: the link between them goes through the air (a sphere about the stock where
// the axis turns, a plane where S1 keeps one axis): the clearance check of the whole program, links
// included, finds no position near the part, and the material removal no gouge (a straight rapid between
// the channels' safe surfaces went through a blade: 5,104 mm³ of S2 "gouge" before).
TEST(Sweep, ChannelsJoinedThroughTheAir) {
  const fixtures::PartCase& c = fixtures::impellerCase();
  for (Strategy strategy : {Strategy::CoaxialCylinders, Strategy::PlanesParallelToFace}) {
    std::vector<std::vector<ToolMove>> regions;
    size_t count = 0;
    for (size_t i = 0; i < 2; ++i) {
      const RemovalSolid& channel = c.volume.solids[i];
      regions.push_back(sweep(roughing::partition(channel, c.shapes.part, strategy), channel, c.shapes.part, c.shapes.stock, {}).moves);
      count += regions.back().size();
    }
    const std::vector<ToolMove> joined = joinSweeps(regions, c.shapes.stock);
    EXPECT_GT(joined.size(), count);
    const SweepSettings settings;
    const ClearanceReport clear = checkClearance(joined, c.shapes.part, settings.cutter, settings.allowance - 0.01, 1.0);
    EXPECT_EQ(clear.tooClose, 0) << strategyName(strategy) << ": closest " << clear.minimum << " at move " << clear.worstMove;
    if (strategy == Strategy::PlanesParallelToFace) {
      for (const ToolMove& m : joined) EXPECT_GT(m.axis.dot(joined.front().axis), 1.0 - 1e-12) << "S1 keeps one axis";
    }
    RemovalSettings coarse;
    coarse.resolution = 0.5;
    const RemovalResult removal = simulateRemoval(joined, settings.cutter, c.shapes.stock, c.shapes.part, coarse);
    EXPECT_LT(removal.gougeVolume, 1.0) << strategyName(strategy) << ": gouge at move " << removal.gougeMove;
  }
}
