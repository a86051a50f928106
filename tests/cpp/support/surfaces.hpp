// Test surfaces built in OCCT for the C++ tests and benchmarks.
#pragma once

#include <TopoDS_Face.hxx>

namespace hsm::test {

// Valleys running at 45° on a size × size square: z = height/2·(1 − cos 2πu/wavelength), u across them,
// a bicubic B-spline through a points × points grid as a CAD system gives it. The concave radius at the
// bottoms is wavelength²/(2π²·height).
TopoDS_Face slantedValleys(double size, double height, double wavelength, int points);

}  // namespace hsm::test
