// A last line of defence for the hosts of the core (FreeCAD, the CLI): OCCT can fail inside its own
// algorithms on degenerate input, by an exception or by a signal (SIGSEGV, SIGFPE). A signal would end
// the process, and in FreeCAD lose the user's unsaved document. `guarded` runs a computation with OCCT's
// signal handlers installed (OSD::SetSignal) and OCC_CATCH_SIGNALS at its door, so that such a signal
// raised in the calling thread becomes a Standard_Failure, then a ComputationError naming the computation;
// the host's own handlers are put back afterwards. Known crashing inputs are refused before OCCT sees them
// (the limits of each capability): this is for the ones not yet known. Our own code must not need it: the
// C++ tests run under AddressSanitizer and UndefinedBehaviorSanitizer (`make test-asan`).
#pragma once

#include "common/error.hpp"

#include <string>

namespace hsm {

namespace detail {
// Installs OCCT's handlers for the duration of the outermost guard (nested and concurrent guards share it).
class SignalScope {
public:
  SignalScope();
  ~SignalScope();
  SignalScope(const SignalScope&) = delete;
  SignalScope& operator=(const SignalScope&) = delete;
};

[[noreturn]] void rethrowOcctFailure(const char* what, const char* message);
}  // namespace detail

template <class Work>
auto guarded(const char* what, Work&& work) -> decltype(work());

}  // namespace hsm

#include "common/occt_guard_impl.hpp"
