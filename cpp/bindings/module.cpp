// hsmplanner._core: thin pybind11 layer over the C++ core. No logic here: argument conversion and
// the mapping of core exceptions to Python ones.
#include "bindings/bindings.hpp"

#include "common/error.hpp"
#include "common/progress.hpp"

#include <memory>

#include <Standard_Failure.hxx>

namespace py = pybind11;

namespace hsm::bindings {
namespace {
struct HeldCallable {
  py::object callable;
  ~HeldCallable() {
    py::gil_scoped_acquire gil;
    callable = py::object();
  }
};
}  // namespace

ProgressCallback progressCallback(const py::object& callable) {
  if (callable.is_none()) return {};
  if (!PyCallable_Check(callable.ptr()))
    throw InputError("progress must be a callable progress(done) returning False to cancel, or None");
  auto held = std::make_shared<HeldCallable>();
  held->callable = callable;
  return [held](double done) {
    py::gil_scoped_acquire gil;
    const py::object answer = held->callable(done);
    return answer.is_none() || answer.cast<bool>();
  };
}
}  // namespace hsm::bindings

PYBIND11_MODULE(_core, module) {
  module.doc() = "HSM Planner C++ core (OCCT + Eigen)";
  module.attr("__version__") = HSM_VERSION;

  py::register_exception_translator([](std::exception_ptr failure) {
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const hsm::InputError& error) {
      PyErr_SetString(PyExc_ValueError, error.what());
    } catch (const hsm::ComputationError& error) {
      PyErr_SetString(PyExc_RuntimeError, error.what());
    } catch (const Standard_Failure& failure) {
      // An OCCT exception that escaped the core is a bug of ours, but it must not take FreeCAD down.
      PyErr_SetString(PyExc_RuntimeError,
                      (std::string("OCCT error in the HSM Planner core: ") + failure.GetMessageString()).c_str());
    }
  });

  // The user stopped a computation (FreeCAD's Esc, or a progress callback returning False).
  py::register_exception<hsm::Cancelled>(module, "Cancelled", PyExc_Exception);

  hsm::bindings::bindGeometry(module);
  hsm::bindings::bindCurvenet(module);
  hsm::bindings::bindKinematics(module);
  hsm::bindings::bindToolpath(module);
  hsm::bindings::bindDirection(module);
  hsm::bindings::bindRoughing(module);
}
