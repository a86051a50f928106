#include "common/fork_safety.hpp"

#include <pthread.h>

#include <atomic>

namespace hsm {
namespace {

std::atomic<bool> forked{false};

void markForked() { forked.store(true); }

// Registered when the core is loaded, before any fork that could matter.
const int registered = pthread_atfork(nullptr, nullptr, markForked);

}  // namespace

bool inForkedChild() { return registered == 0 && forked.load(); }

}  // namespace hsm
