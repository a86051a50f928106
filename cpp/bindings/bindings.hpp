#pragma once

#include "common/occt_guard.hpp"
#include "common/progress.hpp"

#include <Geom_BSplineCurve.hxx>
#include <pybind11/pybind11.h>

namespace hsm::bindings {

// A Python callable progress(done) -> bool or None (done in [0, 1]; False cancels) as the core's callback;
// None gives none. The callable is held so that copies of the callback, made without the GIL, never touch
// its reference count; each call takes the GIL.
ProgressCallback progressCallback(const pybind11::object& callable);

// A B-spline curve handed to Python: the inputs of the nets and toolpaths, and every curve they return.
struct BSplineCurve {
  Handle(Geom_BSplineCurve) curve;
};

void bindGeometry(pybind11::module_& module);
void bindCurvenet(pybind11::module_& module);
void bindKinematics(pybind11::module_& module);
void bindToolpath(pybind11::module_& module);
void bindDirection(pybind11::module_& module);
void bindRoughing(pybind11::module_& module);
// The roughing sweep and its clearance check, in the roughing submodule `m` (bind_sweep.cpp).
void bindSweep(pybind11::module_& m);
}
