#pragma once

#include <pybind11/pybind11.h>

namespace hsm::bindings {
void bindGeometry(pybind11::module_& module);
void bindCurvenet(pybind11::module_& module);
void bindKinematics(pybind11::module_& module);
}
