// The roughing paper's test parts, built in the core so that the C++ tests, the Python API and the FreeCAD
// objects all machine the same shapes.
#pragma once

#include <TopoDS_Shape.hxx>

namespace hsm::roughing {

struct PartAndStock {
  TopoDS_Shape part, stock;
};

// A box with a slot along Y whose axis is tilted from Z about Y: a straight tool along Z cannot reach under
// its overhanging side, a tool tilted by `tiltDeg` reaches it all. The slot's depth is measured along its axis
// from the top face at the axis; its floor is normal to the axis.
struct SlantedSlotParameters {
  double length = 80.0, width = 40.0, height = 30.0;  // the box, mm (X, Y, Z)
  double slotWidth = 16.0, slotDepth = 24.0;          // mm
  double tiltDeg = 30.0;                               // the slot's axis from Z, about Y
};
PartAndStock slantedSlotBlock(const SlantedSlotParameters& p = {});
// Its volume to remove in closed form: slotWidth · slotDepth · width (the top plane cuts the slot's mouth
// symmetrically about the axis, so the slanted mouth adds and takes the same).
double slantedSlotVolume(const SlantedSlotParameters& p);

// A radial compressor impeller (the paper's test part): a hub of revolution whose meridian is a quarter arc
// from the axial inlet to the radial outlet, `blades` blades lofted through sections whose angular position
// shifts with the height above the hub (`leanDeg`: the channels are undercut) and along the flow (`wrapDeg`),
// inside a blank of revolution whose inlet face is a plane and whose outlet face is a cylinder; the blades
// end on the blank's skin (part = (hub ∪ blades) ∩ blank).
struct ImpellerParameters {
  int blades = 7;
  double hubInletRadius = 10.0;    // mm, hub at the inlet plane
  double outletRadius = 50.0;      // mm, the outlet cylinder
  double height = 40.0;            // mm, from the outlet's hub side to the inlet plane
  double channelHeight = 12.0;     // mm, from hub to shroud along the arc's radius
  double leanDeg = 20.0;           // angular shift from hub to tip
  double wrapDeg = 30.0;           // angular shift from inlet to outlet
  double thickness = 2.5;          // mm, blade thickness
  double baseThickness = 5.0;      // mm of hub body below the outlet
};
PartAndStock impeller(const ImpellerParameters& p = {});

}  // namespace hsm::roughing
