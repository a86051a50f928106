#include "roughing/roughing.hpp"
#include "roughing/slicing.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/occt_progress.hpp"
#include "common/text.hpp"

#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <map>

namespace hsm::roughing {

std::string strategyName(Strategy s) {
  switch (s) {
    case Strategy::PlanesParallelToFace: return "S1 planes parallel to a crossable face";
    case Strategy::CoaxialCylinders: return "S2 coaxial cylinders";
    case Strategy::SetupPlanes: return "S3 planes of the setup direction";
    case Strategy::StockOffsets: return "S4 offsets of the stock skin";
    case Strategy::HubOffsets: return "S5 offsets of the hub";
  }
  return "?";
}

namespace {

double volumeOf(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  return props.Mass();
}

// The largest face (1-based) of the largest surface group of the solid that passes `keep`, 0 if none.
template <class Keep>
int largestFace(const RemovalSolid& s, Keep&& keep) {
  int best = 0;
  double bestArea = 0.0;
  for (size_t i = 0; i < s.faceClasses.size(); ++i) {
    if (!keep(s.faceClasses[i], s.faceKinds[i])) continue;
    const double area = s.groupArea(s.faceGroups[i]);
    if (best == 0 || area > bestArea * (1.0 + 1e-9) ||
        (area >= bestArea * (1.0 - 1e-9) && s.faceGroups[i] == s.faceGroups[best - 1] && s.faceAreas[i] > s.faceAreas[best - 1])) {
      best = static_cast<int>(i) + 1;
      bestArea = area;
    }
  }
  return best;
}

// The reference face of `strategy` in the solid (1-based), or 0 when it has none (S3 needs none: 0 too).
int referenceFaceOrNone(const RemovalSolid& s, Strategy strategy) {
  switch (strategy) {
    case Strategy::PlanesParallelToFace:
      return largestFace(s, [](FaceClass c, SurfaceKind k) { return c == FaceClass::Crossable && k == SurfaceKind::Plane; });
    case Strategy::CoaxialCylinders:
      return largestFace(s, [](FaceClass c, SurfaceKind k) { return c == FaceClass::Crossable && k == SurfaceKind::Cylinder; });
    case Strategy::StockOffsets: {
      const int f = largestFace(s, [](FaceClass c, SurfaceKind k) {
        return c == FaceClass::Crossable && k != SurfaceKind::Plane && k != SurfaceKind::Cylinder;
      });
      return f != 0 ? f : largestFace(s, [](FaceClass c, SurfaceKind) { return c == FaceClass::Crossable; });
    }
    case Strategy::HubOffsets:
      return largestFace(s, [](FaceClass c, SurfaceKind) { return c == FaceClass::FacingCrossable; });
    case Strategy::SetupPlanes: return 0;
  }
  return 0;
}

// "S1, S3 or S5": the strategies this solid has the reference face of (S3 always).
std::string applicableStrategies(const RemovalSolid& s) {
  std::vector<std::string> names;
  for (Strategy k : {Strategy::PlanesParallelToFace, Strategy::CoaxialCylinders, Strategy::SetupPlanes,
                     Strategy::StockOffsets, Strategy::HubOffsets})
    if (k == Strategy::SetupPlanes || referenceFaceOrNone(s, k) != 0) names.push_back(strategyName(k).substr(0, 2));
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return out;
}

int referenceFace(const RemovalSolid& s, Strategy strategy) {
  const int f = referenceFaceOrNone(s, strategy);
  if (f != 0 || strategy == Strategy::SetupPlanes) return f;
  const std::string use = ": use " + applicableStrategies(s);
  switch (strategy) {
    case Strategy::PlanesParallelToFace:
      throw InputError("S1 needs a planar crossable face (an inlet plane, a stock top) and this volume has none" + use);
    case Strategy::CoaxialCylinders:
      throw InputError("S2 needs a cylindrical crossable face (an outlet cylinder) and this volume has none" + use);
    case Strategy::StockOffsets: throw InputError("S4 needs a crossable face (the stock skin) and this volume has none" + use);
    default:
      throw InputError("S5 needs a face of the part that faces a crossable face (a hub, a floor) and this volume has "
                       "none" + use);
  }
}

TopoDS_Face faceOf(const RemovalSolid& s, int index) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(s.solid, TopAbs_FACE, faces);
  return TopoDS::Face(faces(index));
}

}  // namespace

constexpr double kSliverMm = 0.01;

namespace {

int faceCount(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return faces.Extent();
}

// "0.25": a step rounded up to two significant digits, so that the step a message offers fits.
double roundedUp(double step) {
  const double unit = std::pow(10.0, std::floor(std::log10(step)) - 1.0);
  return std::ceil(step / unit - 1e-9) * unit;
}

// Estimated seconds of splitting the volume by `surfaces` of the family (SlicingFamily::crossingCost).
double splitSeconds(double surfaces, const SlicingFamily& family, int faces) {
  return surfaces * faces * family.crossingCost() + 0.5 * surfaces * (surfaces - 1.0) * family.pairCost();
}

// The most surfaces whose split is estimated within kMaxPartitionSeconds.
double surfacesThatFit(const SlicingFamily& family, int faces) {
  const double a = 0.5 * family.pairCost(), b = faces * family.crossingCost() - a;
  if (!(a > 0.0)) return std::floor(kMaxPartitionSeconds / b);
  return std::floor((-b + std::sqrt(b * b + 4.0 * a * kMaxPartitionSeconds)) / (2.0 * a));
}

// How many slices of `step` the extent makes, refused when there are more than kMaxSlices or when splitting
// the volume by their surfaces is estimated beyond kMaxPartitionSeconds (its time and memory grow with the
// surfaces, the faces each may cross, and how hard the surfaces are to intersect).
int sliceCount(double extent, double step, const SlicingFamily& family, int faces, Strategy strategy) {
  // A last layer thinner than kSliverMm is the depth's measuring error (offset meridians are polylines), not
  // material: it goes with the layer above.
  const double slices = std::max(1.0, std::ceil((extent - kSliverMm) / step));
  if (slices > kMaxSlices)
    throw InputError("step " + number(step) + " mm gives " + number(slices) + " slices (more than " +
                     std::to_string(kMaxSlices) + "): use a step of at least " +
                     number(roundedUp(extent / kMaxSlices)) + " mm");
  const double seconds = splitSeconds(slices - 1.0, family, faces);
  if (seconds > kMaxPartitionSeconds) {
    const double fit = std::max(1.0, surfacesThatFit(family, faces));
    throw InputError("step " + number(step) + " mm cuts this volume of " + std::to_string(faces) + " faces by " +
                     number(slices - 1.0) + " " + strategyName(strategy).substr(3) + ": about " +
                     number(std::round(seconds)) + " s of splitting on a 2-core machine, more than the " +
                     number(kMaxPartitionSeconds) + " s a partition may take; use a step of at least " +
                     number(roundedUp(extent / (fit + 1.0))) + " mm");
  }
  return static_cast<int>(slices);
}

// The solid split by the family's surfaces at every step from `low` (all at once: BRepAlgoAPI_Splitter).
TopoDS_Shape splitBySurfaces(const TopoDS_Solid& solid, const SlicingFamily& family, double low, double step,
                             int count, Strategy strategy, const ProgressCallback& progress,
                             ProgressReporter& reporter) {
  TopTools_ListOfShape arguments, tools;
  arguments.Append(solid);
  for (int k = 1; k < count; ++k) {
    tools.Append(family.surfaceAt(low + k * step));
    reporter(0.15 + 0.05 * k / count);
  }
  if (tools.IsEmpty()) return solid;
  BRepAlgoAPI_Splitter splitter;
  splitter.SetArguments(arguments);
  splitter.SetTools(tools);
  Handle(OcctProgress) occtProgress = new OcctProgress(progress, 0.2, 0.7);
  splitter.Build(occtProgress->Start());
  occtProgress->throwIfStopped("partition");
  if (!splitter.IsDone() || splitter.HasErrors())
    throw ComputationError("OCCT could not split the volume by the " + strategyName(strategy) + " surfaces");
  return splitter.Shape();
}

// Each piece of the split to its slice, by the depths its boundary spans: a piece between two consecutive
// surfaces spans at most a step, and the middle of its span lies in its slice. A piece that spans more holds a
// surface OCCT left uncut, and is an error rather than a slice with the material of several.
std::map<int, std::vector<TopoDS_Shape>> piecesBySlice(const TopoDS_Shape& pieces, const SlicingFamily& family,
                                                      double low, double step, int count, Strategy strategy,
                                                      ProgressReporter& reporter) {
  std::vector<TopoDS_Shape> solids;
  for (TopExp_Explorer it(pieces, TopAbs_SOLID); it.More(); it.Next()) solids.push_back(it.Current());
  std::map<int, std::vector<TopoDS_Shape>> bySlice;
  for (size_t i = 0; i < solids.size(); ++i) {
    const TopoDS_Shape& piece = solids[i];
    if (!BRepCheck_Analyzer(piece).IsValid())
      throw ComputationError("a piece of the " + strategyName(strategy) + " split is not a valid solid: try another step");
    const auto [from, to] = family.depthRange(piece);
    const double slack = std::max(kSliverMm, 0.05 * step) + 2e-3 * (to - from);
    if (to - from > step + slack)
      throw ComputationError("OCCT's splitter left the " + strategyName(strategy) + " surfaces between depths " +
                             number(from - low) + " and " + number(to - low) +
                             " mm uncut (one piece spans them): try another step");
    const int slice = std::clamp(static_cast<int>(std::floor((0.5 * (from + to) - low) / step)), 0, count - 1);
    bySlice[slice].push_back(piece);
    reporter(0.7 + 0.2 * (i + 1) / solids.size());
  }
  return bySlice;
}

TopoDS_Shape compoundOf(const std::vector<TopoDS_Shape>& shapes) {
  if (shapes.size() == 1) return shapes.front();
  TopoDS_Compound compound;
  BRep_Builder builder;
  builder.MakeCompound(compound);
  for (const TopoDS_Shape& s : shapes) builder.Add(compound, s);
  return compound;
}

}  // namespace

Partition partition(const RemovalSolid& solid, const TopoDS_Shape& part, Strategy strategy,
                    const PartitionSettings& settings) {
  if (solid.solid.IsNull()) throw InputError("the volume to remove is empty: compute it from a stock and a part first");
  if (!(settings.step > 0.0) || !std::isfinite(settings.step))
    throw InputError("step " + number(settings.step) + " mm must be positive: the axial engagement, e.g. 8 mm for a Ø8 tool");
  checkThreads(settings.threads, "partition");
  Partition result;
  result.strategy = strategy;
  result.step = settings.step;
  result.referenceFace = referenceFace(solid, strategy);
  if (strategy == Strategy::StockOffsets &&
      solid.faceKinds[static_cast<size_t>(result.referenceFace - 1)] == SurfaceKind::Plane)
    result.warnings.push_back("S4: the stock skin here is a plane, so its offsets are planes parallel to it: the "
                              "sub-volumes and the path are S1's on that face");
  ProgressReporter reporter(settings.progress, "partition");

  // The slicing family: a depth measure over space and the surface at each depth.
  std::unique_ptr<SlicingFamily> family;
  if (strategy == Strategy::SetupPlanes) {
    PartitionSettings search = settings;
    search.progress = progressPart(settings.progress, 0.0, 0.15);
    const auto [direction, reach] = setupDirection(solid, part, search);
    result.setupDirection = direction;
    result.setupReach = reach;
    family = planesAlong(solid.solid, -direction);  // from the side the tool comes from, inwards
  } else {
    family = familyOf(solid.solid, faceOf(solid, result.referenceFace), strategy);
  }
  const auto [low, high] = family->depthRange(solid.solid);
  const double extent = high - low;
  if (!(extent > 0.0)) throw ComputationError("the volume has no extent along the slicing surfaces");
  if (settings.step > extent)
    throw InputError("step " + number(settings.step) + " mm is larger than the volume's extent of " + number(extent) +
                     " mm along the slicing surfaces: nothing to slice; use a step up to " + number(extent) + " mm");
  const int count = sliceCount(extent, settings.step, *family, faceCount(solid.solid), strategy);
  reporter(0.15);

  const TopoDS_Shape pieces =
      splitBySurfaces(solid.solid, *family, low, settings.step, count, strategy, settings.progress, reporter);
  reporter(0.7);
  for (auto& [slice, shapes] : piecesBySlice(pieces, *family, low, settings.step, count, strategy, reporter)) {
    SubVolume sub;
    sub.slice = slice;
    sub.shape = compoundOf(shapes);
    sub.volume = volumeOf(sub.shape);
    sub.surface = family->surfaceDescription(low + slice * settings.step, result.referenceFace);
    family->axisField(sub.shape, low + slice * settings.step, sub.axisPoints, sub.axisDirections);
    // The field points towards the reference surface: out through a crossable one (S1, S2, S4), but S5's
    // reference is the floor, and the tool stands on the other side of the slice, away from it.
    if (strategy == Strategy::HubOffsets)
      for (Eigen::Vector3d& axis : sub.axisDirections) axis = -axis;
    result.volume += sub.volume;
    result.subVolumes.push_back(std::move(sub));
    reporter(0.9 + 0.1 * result.subVolumes.size() / count);
  }
  if (std::abs(result.volume - solid.volume) > kVolumeTolerance * solid.volume)
    throw ComputationError("the sub-volumes of " + strategyName(strategy) + " add up to " + number(result.volume) +
                           " mm³, not the volume's " + number(solid.volume) + " mm³: the split lost material");
  reporter(1.0);
  return result;
}

}  // namespace hsm::roughing
