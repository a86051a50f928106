// Which parts of a face a 3-axis tool along +Z can reach: without this check a face that looks down, or a
// wall, would be "finished" by passes through the part.
//
// The face is sampled on a grid of its parameters, inside its boundaries. The tool is on the side the
// face's normal points to, as FreeCAD shows it (the surface's normal, turned when the face is reversed):
// for a face of a solid that is out of the material; a face of a surface model that points the wrong way
// is refused with the hint to reverse it. A sample is reachable when that normal points up by more than
// kReachSlope (1°): a ball then rests on the face from above. Vertical parts are reached only by the
// ball's side (waterline work) and parts that face down not at all.
#pragma once

#include <TopoDS_Face.hxx>

#include <string>

namespace hsm::toolpath {

inline constexpr double kReachSlope = 0.01745;  // sin 1°: faces steeper than 89° are walls

struct Reach {
  int samples = 0;
  double up = 0.0, vertical = 0.0, down = 0.0;  // shares of the samples (sum 1)
  double toolSide = 1.0;  // +1: the tool is on the side of the surface's natural normal Su × Sv, −1 the other
};

Reach reachability(const TopoDS_Face& face);

// Refuses a face the tool cannot reach at all (InputError naming `faceName`, why, and what can finish it);
// returns a warning (empty when none) when only part of it is reachable.
std::string checkReach(const Reach& reach, const std::string& faceName);

}  // namespace hsm::toolpath
