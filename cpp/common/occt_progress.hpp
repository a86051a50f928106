// OCCT's long operations (booleans, the splitter) report progress and stop on request through a
// Message_ProgressIndicator: this one forwards their progress to the core's callback, mapped into
// [from, to] of the caller's work, and asks OCCT to stop when the callback says cancel. OCCT then returns with
// errors; the caller checks cancelled() and throws hsm::Cancelled (never through OCCT's frames).
#pragma once

#include "common/progress.hpp"

#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressScope.hxx>

#include <atomic>
#include <chrono>

namespace hsm {

class OcctProgress : public Message_ProgressIndicator {
public:
  OcctProgress(ProgressCallback callback, double from, double to)
      : callback_(std::move(callback)), from_(from), to_(to) {}

  bool cancelled() const { return cancelled_; }

protected:
  // OCCT calls Show under its own mutex, so the callback is never entered twice at once.
  void Show(const Message_ProgressScope&, const Standard_Boolean force) override {
    if (!callback_ || cancelled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    shown_ = true;
    last_ = now;
    if (!callback_(from_ + (to_ - from_) * GetPosition())) cancelled_ = true;
  }
  Standard_Boolean UserBreak() override { return cancelled_; }

private:
  ProgressCallback callback_;
  double from_, to_;
  std::atomic<bool> cancelled_{false};
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace hsm
