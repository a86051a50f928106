#include "roughing/roughing.hpp"
#include "common/fork_safety.hpp"
#include "geometry/bounds.hpp"
#include "geometry/mesh.hpp"

#include "common/error.hpp"
#include "common/occt_progress.hpp"
#include "common/text.hpp"
#include "roughing/rays.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <Bnd_Box.hxx>
#include <Poly_Triangulation.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepLProp_SLProps.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <gp_Pnt2d.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>

namespace hsm::roughing {

int RemovalSolid::groupCount() const {
  return faceGroups.empty() ? 0 : *std::max_element(faceGroups.begin(), faceGroups.end()) + 1;
}

double RemovalSolid::groupArea(int group) const {
  double area = 0.0;
  for (size_t i = 0; i < faceGroups.size(); ++i)
    if (faceGroups[i] == group) area += faceAreas[i];
  return area;
}

std::string faceClassName(FaceClass c) {
  switch (c) {
    case FaceClass::Crossable: return "crossable";
    case FaceClass::FacingCrossable: return "facing_crossable";
    case FaceClass::NotCrossable: return "not_crossable";
  }
  return "?";
}

namespace {

const double kVisAVis = std::cos(M_PI / 4.0);

double solidVolume(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  return props.Mass();
}

double faceArea(const TopoDS_Shape& face) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  return props.Mass();
}

// A closed, valid solid with a positive volume, or InputError naming `what`.
double checkedSolid(const TopoDS_Shape& shape, const std::string& what) {
  if (shape.IsNull()) throw InputError("the " + what + " is empty: pick a solid");
  if (!TopExp_Explorer(shape, TopAbs_SOLID).More())
    throw InputError("the " + what + " holds no solid (a surface or a wire?): give a closed solid");
  if (!BRepCheck_Analyzer(shape).IsValid())
    throw InputError("the " + what + " is not a valid solid (BRepCheck): repair it (Part ▸ Check geometry) first");
  const double volume = solidVolume(shape);
  if (!(volume > 0.0) || !std::isfinite(volume))
    throw InputError("the " + what + " has no volume (" + number(volume) + " mm³): is it a closed solid, oriented outwards?");
  return volume;
}

SurfaceKind kindOf(const TopoDS_Face& face) {
  switch (BRepAdaptor_Surface(face).GetType()) {
    case GeomAbs_Plane: return SurfaceKind::Plane;
    case GeomAbs_Cylinder: return SurfaceKind::Cylinder;
    case GeomAbs_SurfaceOfRevolution: case GeomAbs_Cone: case GeomAbs_Sphere: case GeomAbs_Torus:
      return SurfaceKind::Revolution;
    default: return SurfaceKind::Other;
  }
}

// The faces of the result that come from the stock: unchanged stock faces, and what the cut made of them.
TopTools_MapOfShape stockFaces(BRepAlgoAPI_Cut& cut, const TopoDS_Shape& stock) {
  TopTools_MapOfShape from;
  for (TopExp_Explorer it(stock, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Shape& face = it.Current();
    const TopTools_ListOfShape& modified = cut.Modified(face);
    for (TopTools_ListOfShape::Iterator m(modified); m.More(); m.Next()) from.Add(m.Value());
    if (modified.IsEmpty() && !cut.IsDeleted(face)) from.Add(face);
  }
  return from;
}

// A point at the middle of the face's parameter box (moved onto the face when the face is trimmed around it)
// and the normal there, pointing out of the solid.
bool faceCentre(const TopoDS_Face& face, gp_Pnt& point, gp_Dir& outward) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  BRepAdaptor_Surface surface(face);
  BRepLProp_SLProps props(surface, 0.5 * (u0 + u1), 0.5 * (v0 + v1), 1, 1e-9);
  if (!props.IsNormalDefined()) return false;
  point = props.Value();
  outward = props.Normal();
  if (face.Orientation() == TopAbs_REVERSED) outward.Reverse();
  return true;
}

// Surface groups that share an edge: neighbours[g] holds g's.
std::vector<std::vector<bool>> neighbourGroups(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces,
                                               const std::vector<int>& groups, int groupCount) {
  std::vector<std::vector<bool>> neighbours(static_cast<size_t>(groupCount), std::vector<bool>(static_cast<size_t>(groupCount), false));
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int e = 1; e <= edgeFaces.Extent(); ++e)
    for (const TopoDS_Shape& a : edgeFaces(e))
      for (const TopoDS_Shape& b : edgeFaces(e)) {
        const int ia = faces.FindIndex(a), ib = faces.FindIndex(b);
        if (ia > 0 && ib > 0) neighbours[static_cast<size_t>(groups[ia - 1])][static_cast<size_t>(groups[ib - 1])] = true;
      }
  return neighbours;
}

// Whether most of the face is vis-à-vis a crossable surface: of the rays along its normal into the volume from a
// 5 × 5 grid of its parameters (the points on the face), more than half first meet a crossable face across the
// volume, not a neighbour (a wall opening onto the skin sees the skin past their common edge: it does not face
// it), whose normal is within 45° of opposite to the ray (not a grazing exit).
bool seesCrossable(const RayCaster& rays, const TopoDS_Face& face, const TopTools_IndexedMapOfShape& faces,
                   const std::vector<FaceClass>& classes, const std::vector<int>& groups,
                   const std::vector<bool>& neighbour) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  BRepAdaptor_Surface surface(face);
  BRepTopAdaptor_FClass2d inside(face, 1e-7);
  int seen = 0, crossable = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / 5, v = v0 + (v1 - v0) * (j + 0.5) / 5;
      if (inside.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
      BRepLProp_SLProps props(surface, u, v, 1, 1e-9);
      if (!props.IsNormalDefined()) continue;
      gp_Dir inward = props.Normal();
      if (face.Orientation() != TopAbs_REVERSED) inward.Reverse();
      const RayHit first = rays.nearest(gp_Lin(props.Value(), inward), 1e-6, 1e12);
      if (first.face < 0) continue;
      const int hit = faces.FindIndex(rays.faces()[static_cast<size_t>(first.face)]);
      ++seen;
      if (hit == 0 || classes[hit - 1] != FaceClass::Crossable || neighbour[static_cast<size_t>(groups[hit - 1])]) continue;
      const TopoDS_Face& exit = TopoDS::Face(faces(hit));
      BRepAdaptor_Surface exitSurface(exit);
      BRepLProp_SLProps exitProps(exitSurface, first.u, first.v, 1, 1e-9);
      if (!exitProps.IsNormalDefined()) continue;
      gp_Dir exitOutward = exitProps.Normal();
      if (exit.Orientation() == TopAbs_REVERSED) exitOutward.Reverse();
      crossable += exitOutward.Dot(inward) > kVisAVis;
    }
  return seen > 0 && 2 * crossable > seen;
}

// Faces of one surface (the same geometry, as a periodic surface's seam or a boolean leaves it) in one group.
std::vector<int> surfaceGroups(const TopTools_IndexedMapOfShape& faces) {
  std::vector<int> groups(static_cast<size_t>(faces.Extent()), -1);
  int next = 0;
  for (int i = 1; i <= faces.Extent(); ++i) {
    if (groups[i - 1] >= 0) continue;
    groups[i - 1] = next;
    TopLoc_Location li;
    const Handle(Geom_Surface) si = BRep_Tool::Surface(TopoDS::Face(faces(i)), li);
    for (int k = i + 1; k <= faces.Extent(); ++k) {
      TopLoc_Location lk;
      if (groups[k - 1] < 0 && BRep_Tool::Surface(TopoDS::Face(faces(k)), lk) == si && lk.IsEqual(li)) groups[k - 1] = next;
    }
    ++next;
  }
  return groups;
}

RemovalSolid classify(const TopoDS_Solid& solid, const TopTools_MapOfShape& fromStock) {
  RemovalSolid r;
  r.solid = solid;
  r.volume = solidVolume(solid);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  r.faceGroups = surfaceGroups(faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i));
    r.faceClasses.push_back(fromStock.Contains(face) ? FaceClass::Crossable : FaceClass::NotCrossable);
    r.faceKinds.push_back(kindOf(face));
    r.faceAreas.push_back(faceArea(face));
  }
  // A part's surface is facing_crossable when most of its largest face sees a crossable face.
  const std::vector<std::vector<bool>> neighbours = neighbourGroups(solid, faces, r.faceGroups, r.groupCount());
  const RayCaster rays(solid, 1e-7);  // made once: it prepares every face of the solid
  for (int g = 0; g < r.groupCount(); ++g) {
    int largest = 0;
    for (int i = 1; i <= faces.Extent(); ++i)
      if (r.faceGroups[i - 1] == g && (largest == 0 || r.faceAreas[i - 1] > r.faceAreas[largest - 1])) largest = i;
    if (r.faceClasses[largest - 1] == FaceClass::Crossable) continue;
    if (!seesCrossable(rays, TopoDS::Face(faces(largest)), faces, r.faceClasses, r.faceGroups,
                       neighbours[static_cast<size_t>(g)]))
      continue;
    for (int i = 1; i <= faces.Extent(); ++i)
      if (r.faceGroups[i - 1] == g) r.faceClasses[i - 1] = FaceClass::FacingCrossable;
  }
  return r;
}

bool checkedCut(BRepAlgoAPI_Cut& cut, double expected, std::string& why) {
  if (!cut.IsDone() || cut.HasErrors()) {
    why = "the boolean cut reported an error";
    return false;
  }
  why = cutProblem(cut.Shape(), expected);
  return why.empty();
}

}  // namespace

std::string cutProblem(const TopoDS_Shape& result, double expected) {
  if (result.IsNull() || !TopExp_Explorer(result, TopAbs_SOLID).More()) return "the cut gave no solid";
  if (!BRepCheck_Analyzer(result).IsValid()) return "the cut gave an invalid solid (BRepCheck)";
  const double volume = solidVolume(result);
  if (std::abs(volume - expected) > kVolumeTolerance * std::max(expected, 1.0))
    return "the cut's volume " + number(volume) + " mm³ is not the stock's less the part's (" + number(expected) + " mm³)";
  return {};
}

VolumeToRemove volumeToRemove(const TopoDS_Shape& stock, const TopoDS_Shape& part, const ProgressCallback& progress) {
  VolumeToRemove v;
  v.partVolume = checkedSolid(part, "part");
  v.stockVolume = checkedSolid(stock, "stock");
  // The stock must hold the part: no node of the part's mesh lies outside it (a boolean part − stock would
  // cost as much as the cut itself).
  {
    Bnd_Box box = geometry::exactBounds(part);
    const double size = std::sqrt(box.SquareExtent());
    geometry::meshShape(part, 2e-3 * size, 0.5, occtMayRunInParallel());
    BRepClass3d_SolidClassifier inStock(stock);
    for (TopExp_Explorer it(part, TopAbs_FACE); it.More(); it.Next()) {
      TopLoc_Location location;
      const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(TopoDS::Face(it.Current()), location);
      if (mesh.IsNull()) continue;
      auto outside = [&](const gp_Pnt& point, double tolerance) {
        inStock.Perform(point.Transformed(location.Transformation()), tolerance);
        return inStock.State() == TopAbs_OUT;
      };
      // Nodes, and on planes the centres of triangles (a box's face has nodes at its corners only, which may
      // all lie on a smaller stock; a curved face has nodes inside it, and its triangles' centres leave it).
      bool out = false;
      for (int i = 1; i <= mesh->NbNodes() && !out; i += std::max(1, mesh->NbNodes() / 200))
        out = outside(mesh->Node(i), 1e-4 * size);
      const bool planar = BRepAdaptor_Surface(TopoDS::Face(it.Current())).GetType() == GeomAbs_Plane;
      for (int i = 1; planar && i <= mesh->NbTriangles() && !out; i += std::max(1, mesh->NbTriangles() / 200)) {
        int a, b, c;
        mesh->Triangle(i).Get(a, b, c);
        out = outside(gp_Pnt((mesh->Node(a).XYZ() + mesh->Node(b).XYZ() + mesh->Node(c).XYZ()) / 3.0), 1e-4 * size);
      }
      if (out)
        throw InputError("the stock does not contain the part (a point of the part lies outside it): pick a larger "
                         "stock, or check that the two are placed together");
    }
  }
  const double expected = v.stockVolume - v.partVolume;
  if (expected < -kVolumeTolerance * v.stockVolume)
    throw InputError("the stock (" + number(v.stockVolume) + " mm³) is smaller than the part (" + number(v.partVolume) +
                     " mm³): it does not contain the part; pick the blank as the stock and the finished part as the part");
  if (expected <= kVolumeTolerance * v.stockVolume)
    throw InputError("the stock is the part (nothing to remove: " + number(expected) + " mm³): pick the blank, not the part");
  std::string why;
  Handle(OcctProgress) cutProgress = new OcctProgress(progress, 0.1, 0.6);
  BRepAlgoAPI_Cut cut(stock, part, cutProgress->Start());
  cutProgress->throwIfStopped("stock − part");
  BRepAlgoAPI_Cut fuzzy;
  BRepAlgoAPI_Cut* done = &cut;
  if (!checkedCut(cut, expected, why)) {
    const std::string first = why;
    TopTools_ListOfShape arguments, tools;
    arguments.Append(stock);
    tools.Append(part);
    fuzzy.SetArguments(arguments);
    fuzzy.SetTools(tools);
    fuzzy.SetFuzzyValue(kFuzzyValue);
    Handle(OcctProgress) fuzzyProgress = new OcctProgress(progress, 0.6, 0.8);
    fuzzy.Build(fuzzyProgress->Start());
    fuzzyProgress->throwIfStopped("stock − part");
    if (!checkedCut(fuzzy, expected, why))
      throw ComputationError("stock − part failed: " + first + "; again with a fuzzy value of " + number(kFuzzyValue) +
                             " mm: " + why + ". Check both solids (Part ▸ Check geometry)");
    v.fuzzyRetry = true;
    v.warnings.push_back("the cut needed a fuzzy value of " + number(kFuzzyValue) + " mm (" + first + ")");
    done = &fuzzy;
  }
  // Faces that one surface was split into (by the cut, or a periodic surface's seam) are merged back: a
  // region's face is one face, as the paper counts them.
  ShapeUpgrade_UnifySameDomain unify(done->Shape(), Standard_True, Standard_False, Standard_False);
  unify.Build();
  // The cut's history names the faces that come from the stock; the merge's history follows them (when OCCT
  // keeps none, a merged face comes from the stock when its centre lies on the stock's boundary).
  const Handle(BRepTools_History)& merges = unify.History();
  TopTools_MapOfShape fromStock;
  const TopTools_MapOfShape cutFromStock = stockFaces(*done, stock);
  for (TopTools_MapOfShape::Iterator it(cutFromStock); it.More(); it.Next()) {
    if (merges.IsNull()) break;
    const TopTools_ListOfShape& merged = merges->Modified(it.Key());
    if (merged.IsEmpty()) fromStock.Add(it.Key());
    for (TopTools_ListOfShape::Iterator m(merged); m.More(); m.Next()) fromStock.Add(m.Value());
  }
  if (merges.IsNull()) {
    BRepClass3d_SolidClassifier onStock(stock);
    for (TopExp_Explorer it(unify.Shape(), TopAbs_FACE); it.More(); it.Next()) {
      gp_Pnt centre;
      gp_Dir outward;
      if (!faceCentre(TopoDS::Face(it.Current()), centre, outward)) continue;
      onStock.Perform(centre, 1e-6);
      if (onStock.State() == TopAbs_ON) fromStock.Add(it.Current());
    }
  }
  ProgressReporter reporter(progress, "stock − part");
  reporter(0.8);
  for (TopExp_Explorer it(unify.Shape(), TopAbs_SOLID); it.More(); it.Next()) {
    v.solids.push_back(classify(TopoDS::Solid(it.Current()), fromStock));
    reporter(0.8 + 0.02 * static_cast<double>(v.solids.size()));
  }
  reporter(1.0);
  std::sort(v.solids.begin(), v.solids.end(), [](const RemovalSolid& a, const RemovalSolid& b) { return a.volume > b.volume; });
  for (const RemovalSolid& s : v.solids) v.volume += s.volume;
  return v;
}

}  // namespace hsm::roughing
