#include "curvenet/fitting.hpp"

#include "common/error.hpp"

#include <Extrema_LocateExtPC.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include <algorithm>
#include <cmath>

namespace hsm::curvenet::detail {

std::pair<Handle(Geom_BSplineCurve), double> fitCurve(const PointArray& points, double tolerance) {
  const int n = static_cast<int>(points.rows());
  if (n < 2) throw InputError("an intermediate curve needs at least 2 planes; use a smaller step P");
  if (n > kMaxPlanes + 1)  // the layout refuses such steps; a guard for OCCT's approximation, which fails past it
    throw InputError("an intermediate curve on " + std::to_string(n) + " planes exceeds the limit of " +
                     std::to_string(kMaxPlanes) + ": use a larger step P");
  TColgp_Array1OfPnt array(1, n);
  for (int i = 0; i < n; ++i) array.SetValue(i + 1, gp_Pnt(points(i, 0), points(i, 1), points(i, 2)));
  const int degree = std::min(5, n - 1);
  Handle(Geom_BSplineCurve) curve;
  try {
    GeomAPI_PointsToBSpline fit(array, Approx_ChordLength, degree, degree, degree >= 3 ? GeomAbs_C2 : GeomAbs_C1,
                                tolerance);
    if (!fit.IsDone()) throw ComputationError("OCCT could not fit a B-spline to the intermediate points");
    curve = fit.Curve();
  } catch (const Standard_Failure& failure) {
    throw ComputationError(std::string("OCCT failed to fit an intermediate curve: ") + failure.GetMessageString());
  }
  // A fit whose poles fly far from its points oscillates between them; refuse it rather than hand on a
  // curve that later operations (face split, sampling) cannot digest.
  Eigen::AlignedBox3d pointBox, poleBox;
  for (int i = 0; i < n; ++i) pointBox.extend(Eigen::Vector3d(points.row(i).transpose()));
  for (int i = 1; i <= curve->NbPoles(); ++i) {
    const gp_Pnt pole = curve->Pole(i);
    poleBox.extend(Eigen::Vector3d(pole.X(), pole.Y(), pole.Z()));
  }
  const double size = std::max(pointBox.diagonal().norm(), 1.0);
  if ((poleBox.min() - pointBox.min()).minCoeff() < -size || (poleBox.max() - pointBox.max()).maxCoeff() > size)
    throw ComputationError("the B-spline fitted to an intermediate curve oscillates between its points: use a "
                           "larger step P or fit tolerance");
  // The deviation is measured, not assumed: the approximation may stop short of the tolerance.
  GeomAdaptor_Curve adaptor(curve);
  const double t0 = curve->FirstParameter(), t1 = curve->LastParameter();
  double deviation = 0.0, guess = t0;
  double chord = 0.0, total = 0.0;
  for (int i = 1; i < n; ++i) total += array(i + 1).Distance(array(i));
  for (int i = 0; i < n; ++i) {
    if (i > 0) chord += array(i + 1).Distance(array(i));
    guess = total > 0 ? t0 + (t1 - t0) * chord / total : t0;
    Extrema_LocateExtPC locate(array(i + 1), adaptor, guess, 1e-10);
    const double distance = locate.IsDone() ? std::sqrt(locate.SquareDistance())
                                            : array(i + 1).Distance(curve->Value(guess));
    deviation = std::max(deviation, distance);
  }
  return {curve, deviation};
}

}  // namespace hsm::curvenet::detail
