// OCCT's long operations (booleans, the splitter) report progress and stop on request through a
// Message_ProgressIndicator: this one forwards their progress to the core's callback, mapped into
// [from, to] of the caller's work, and asks OCCT to stop when the callback says cancel. OCCT then returns with
// errors; the caller's throwIfStopped throws hsm::Cancelled (never through OCCT's frames).
#pragma once

#include "common/progress.hpp"

#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>

#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

namespace hsm {

class OcctProgress : public Message_ProgressIndicator {
public:
  OcctProgress(ProgressCallback callback, double from, double to)
      : callback_(std::move(callback)), from_(from), to_(to), caller_(std::this_thread::get_id()) {}

  // After OCCT returns: throws what the callback threw (a Python error), or Cancelled when it said stop.
  void throwIfStopped(const std::string& what) const {
    if (error_) std::rethrow_exception(error_);
    if (cancelled_) throw Cancelled(what);
  }

protected:
  void Show(const Message_ProgressScope&, const Standard_Boolean force) override { ask(force); }
  // OCCT asks this between steps that need not report (one face pair's intersection, the next pair): asking
  // the callback here too hears a cancel within its 0.1 s, where Show may not come for long.
  Standard_Boolean UserBreak() override {
    ask(false);
    return cancelled_;
  }

private:
  // The callback at most every 0.1 s, and only from the thread that started the operation: a GUI's callback
  // (Qt, Python) belongs to it; OCCT's workers, were it run in parallel, only read cancelled_.
  void ask(bool force) {
    if (!callback_ || cancelled_ || std::this_thread::get_id() != caller_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    shown_ = true;
    last_ = now;
    try {
      if (!callback_(from_ + (to_ - from_) * GetPosition())) cancelled_ = true;
    } catch (...) {  // never through OCCT's frames
      error_ = std::current_exception();
      cancelled_ = true;
    }
  }

  ProgressCallback callback_;
  double from_, to_;
  std::atomic<bool> cancelled_{false};
  std::thread::id caller_;
  std::exception_ptr error_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace hsm
