#include "toolpath/reach.hpp"

#include "common/error.hpp"
#include "geometry/face_drop.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <sstream>

namespace hsm::toolpath {

namespace {
constexpr int kGrid = 32;

std::string percent(double share) {
  std::ostringstream text;
  text.precision(3);
  text << 100.0 * share << " %";
  return text.str();
}
}  // namespace

Reach reachability(const TopoDS_Face& face) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  if (surface.IsNull()) throw InputError("the face has no surface: pass a face of a solid or a surface model");
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const geometry::UVClassifier inside(face);
  // Natural normals Su × Sv at the samples inside the face; the tool side follows from the orientation.
  std::vector<double> nz;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const double u = u0 + (u1 - u0) * (i + 0.5) / kGrid, v = v0 + (v1 - v0) * (j + 0.5) / kGrid;
      if (!inside.inside(u, v)) continue;
      gp_Pnt p;
      gp_Vec su, sv;
      surface->D1(u, v, p, su, sv);
      const gp_Vec n = su.Crossed(sv);
      if (n.Magnitude() < 1e-14) continue;  // a singular point (a cone's apex): no normal
      nz.push_back(n.Z() / n.Magnitude());
    }
  Reach reach;
  reach.samples = static_cast<int>(nz.size());
  if (nz.empty()) return reach;
  reach.toolSide = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
  for (double z : nz) {
    const double up = reach.toolSide * z;
    (up > kReachSlope ? reach.up : up < -kReachSlope ? reach.down : reach.vertical) += 1.0;
  }
  reach.up /= reach.samples;
  reach.vertical /= reach.samples;
  reach.down /= reach.samples;
  return reach;
}

std::string checkReach(const Reach& reach, const std::string& faceName) {
  if (reach.samples == 0)
    throw InputError(faceName + " has no area inside its boundaries that could be sampled: pass a face with "
                     "an area (an empty or degenerate face cannot be finished)");
  if (reach.up == 0.0 && reach.down == 0.0)
    throw InputError(faceName + " is vertical (its normal is horizontal everywhere): a ball-end tool along Z "
                     "only touches it with its side; finish walls with a Z-level (waterline) contour, and pick "
                     "the bottom face for this operation");
  if (reach.up == 0.0)
    throw InputError(faceName + " faces down (" + percent(reach.down) + " of it looks below the horizontal" +
                     (reach.vertical > 0.0 ? ", the rest is vertical" : "") + "): a tool along +Z cannot reach it "
                     "without cutting through the part; finish it from a second setup with the part turned over, or "
                     "with a tilted (5-axis) tool. (A face of a surface model whose normal points the wrong way: "
                     "reverse it, Face.reversed() in FreeCAD.)");
  if (reach.up < 1.0)
    return percent(1.0 - reach.up) + " of " + faceName + " is vertical or faces down: a tool along +Z cannot "
           "reach those parts; they are left unmachined (finish them from another setup or with a tilted tool)";
  return {};
}

}  // namespace hsm::toolpath
