// Progress of long computations, and their cancellation by the user (FreeCAD's progress bar, Esc).
#pragma once

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

namespace hsm {

// Called with the share of the work done, in [0, 1]; returns false to cancel the computation.
using ProgressCallback = std::function<bool(double done)>;

// The user cancelled a computation through its progress callback (maps to hsmplanner.Cancelled).
class Cancelled : public std::runtime_error {
public:
  explicit Cancelled(const std::string& what) : std::runtime_error(what + " cancelled") {}
};

// Reports to a callback at most every 0.1 s (a GUI repaints then), and throws Cancelled when it says stop.
class ProgressReporter {
public:
  ProgressReporter(ProgressCallback callback, std::string what)
      : callback_(std::move(callback)), what_(std::move(what)) {}

  void operator()(double done) {
    if (!callback_) return;
    const auto now = std::chrono::steady_clock::now();
    if (started_ && now - last_ < std::chrono::milliseconds(100) && done < 1.0) return;
    started_ = true;
    last_ = now;
    if (!callback_(done < 0.0 ? 0.0 : done > 1.0 ? 1.0 : done)) throw Cancelled(what_);
  }

private:
  ProgressCallback callback_;
  std::string what_;
  bool started_ = false;
  std::chrono::steady_clock::time_point last_;
};

// A part [from, to] of a computation's progress as a callback of its own (none stays none).
inline ProgressCallback progressPart(const ProgressCallback& callback, double from, double to) {
  if (!callback) return {};
  return [callback, from, to](double done) { return callback(from + (to - from) * done); };
}

}  // namespace hsm
