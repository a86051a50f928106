#include "surfaces.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <cmath>

namespace hsm::test {

TopoDS_Face slantedValleys(double size, double height, double wavelength, int points) {
  TColgp_Array2OfPnt grid(1, points, 1, points);
  for (int i = 1; i <= points; ++i)
    for (int j = 1; j <= points; ++j) {
      const double x = size * (i - 1) / (points - 1), y = size * (j - 1) / (points - 1), u = (y - x) / std::sqrt(2.0);
      grid.SetValue(i, j, gp_Pnt(x, y, 0.5 * height * (1.0 - std::cos(2.0 * M_PI * u / wavelength))));
    }
  const Handle(Geom_BSplineSurface) surface = GeomAPI_PointsToBSplineSurface(grid, 3, 8, GeomAbs_C2, 1e-6).Surface();
  return BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
}

}  // namespace hsm::test
