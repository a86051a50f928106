// The guard of the hosts: a signal inside a guarded computation becomes a ComputationError, OCCT exceptions
// too, and the host's signal handlers are put back afterwards.
#include "common/occt_guard.hpp"

#include <Standard_ConstructionError.hxx>
#include <gtest/gtest.h>

#include <csignal>
#include <string>

namespace {
void hostHandler(int) {}
}

TEST(OcctGuard, ASignalInsideBecomesAComputationErrorAndTheHostHandlerIsRestored) {
  struct sigaction host {}, before {}, after {};
  host.sa_handler = hostHandler;
  sigemptyset(&host.sa_mask);
  sigaction(SIGSEGV, &host, &before);
  try {
    hsm::guarded("test computation", [] {
      std::raise(SIGSEGV);
      return 0;
    });
    ADD_FAILURE() << "no error";
  } catch (const hsm::ComputationError& error) {
    EXPECT_NE(std::string(error.what()).find("test computation"), std::string::npos) << error.what();
  }
  sigaction(SIGSEGV, nullptr, &after);
  EXPECT_EQ(after.sa_handler, &hostHandler);
  sigaction(SIGSEGV, &before, nullptr);
}

TEST(OcctGuard, OcctExceptionsBecomeComputationErrorsAndResultsPassThrough) {
  EXPECT_THROW(hsm::guarded("construction", []() -> int { throw Standard_ConstructionError("degenerate"); }),
               hsm::ComputationError);
  EXPECT_THROW(hsm::guarded("input", []() -> int { throw hsm::InputError("bad K"); }), hsm::InputError);
  EXPECT_EQ(hsm::guarded("sum", [] { return 2 + 3; }), 5);
}
