#pragma once

#include <Geom_BSplineCurve.hxx>
#include <pybind11/pybind11.h>

namespace hsm::bindings {

// A B-spline curve handed to Python: the inputs of the nets and toolpaths, and every curve they return.
struct BSplineCurve {
  Handle(Geom_BSplineCurve) curve;
};

void bindGeometry(pybind11::module_& module);
void bindCurvenet(pybind11::module_& module);
void bindKinematics(pybind11::module_& module);
void bindToolpath(pybind11::module_& module);
void bindDirection(pybind11::module_& module);
}
