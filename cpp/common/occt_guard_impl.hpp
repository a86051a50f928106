// Template part of occt_guard.hpp: OCC_CATCH_SIGNALS must sit in the frame that catches.
#pragma once

#ifndef OCC_CONVERT_SIGNALS
#define OCC_CONVERT_SIGNALS  // Debian's OCCT is built with it: signals jump to the nearest OCC_CATCH_SIGNALS
#endif
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

namespace hsm {

template <class Work>
auto guarded(const char* what, Work&& work) -> decltype(work()) {
  detail::SignalScope scope;
  try {
    OCC_CATCH_SIGNALS
    return work();
  } catch (const Standard_Failure& failure) {
    detail::rethrowOcctFailure(what, failure.GetMessageString());
  }
}

}  // namespace hsm
