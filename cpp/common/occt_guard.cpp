#include "common/occt_guard.hpp"

#include <OSD.hxx>

#include <csignal>
#include <mutex>

namespace hsm::detail {

namespace {
// Signals OSD::SetSignal takes over; the host's handlers of all of them are saved and put back.
constexpr int kSignals[] = {SIGFPE, SIGHUP, SIGINT, SIGQUIT, SIGILL, SIGBUS, SIGSEGV};

std::mutex& scopeMutex() {
  static std::mutex mutex;
  return mutex;
}
int depth = 0;
struct sigaction saved[sizeof(kSignals) / sizeof(kSignals[0])];
}  // namespace

SignalScope::SignalScope() {
  const std::lock_guard<std::mutex> lock(scopeMutex());
  if (depth++ > 0) return;
  for (size_t i = 0; i < sizeof(kSignals) / sizeof(kSignals[0]); ++i) sigaction(kSignals[i], nullptr, &saved[i]);
  OSD::SetSignal(OSD_SignalMode_Set, /*theFloatingSignal=*/false);  // no floating-point traps: we test isfinite
  // Keyboard interrupts stay the host's (Python's Ctrl-C), as do hang-up and quit.
  for (size_t i = 0; i < sizeof(kSignals) / sizeof(kSignals[0]); ++i)
    if (kSignals[i] == SIGINT || kSignals[i] == SIGHUP || kSignals[i] == SIGQUIT) sigaction(kSignals[i], &saved[i], nullptr);
}

SignalScope::~SignalScope() {
  const std::lock_guard<std::mutex> lock(scopeMutex());
  if (--depth > 0) return;
  for (size_t i = 0; i < sizeof(kSignals) / sizeof(kSignals[0]); ++i) sigaction(kSignals[i], &saved[i], nullptr);
}

void rethrowOcctFailure(const char* what, const char* message) {
  throw ComputationError(std::string("OCCT failed inside the ") + what + " (" + (message ? message : "no message") +
                         "): the computation was stopped and nothing was changed; if it was a signal (access "
                         "violation), save your document and restart FreeCAD, and report the input");
}

}  // namespace hsm::detail
