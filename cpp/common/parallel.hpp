// Work split over threads in contiguous slices. An exception in a worker (an OCCT failure, a Cancelled)
// would end the process if it left the thread: it is kept and thrown again in the caller after the join.
#pragma once

#include "common/error.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <utility>
#include <thread>
#include <vector>

namespace hsm {

// More threads than this is a mistake, not a machine: a settings check refuses it by name (checkThreads), and
// the workers below never start more, whatever they are asked.
constexpr int kMaxThreads = 256;

// `threads` (0: all cores) as a count of threads to start: 1 to kMaxThreads.
inline int threadCount(int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::min(threads, kMaxThreads);
}

// InputError naming `what` for a thread count outside 0 (all cores) to kMaxThreads.
inline void checkThreads(int threads, const std::string& what) {
  if (threads < 0 || threads > kMaxThreads)
    throw InputError(what + ": threads " + std::to_string(threads) + " must be 0 (all cores) to " +
                     std::to_string(kMaxThreads));
}

// Joins the threads started when the next cannot start (the system refuses one: std::system_error), so that
// the error reaches the caller instead of ending the process on a joinable thread's destructor.
template <class Body>
void startEach(std::vector<std::thread>& pool, long count, Body&& body) {
  try {
    for (long k = 0; k < count; ++k) pool.emplace_back(body, k);
  } catch (...) {
    for (auto& t : pool) t.join();
    throw;
  }
}

// Calls work(from, to) over [0, n) on `threads` threads (0: all cores), at most one per `grain` items.
template <class Work>
void parallelSlices(long n, int threads, long grain, Work&& work) {
  threads = static_cast<int>(std::min<long>(threadCount(threads), std::max<long>(1, n / std::max<long>(1, grain))));
  if (threads == 1) return work(0L, n);
  std::exception_ptr failure;
  std::mutex mutex;
  std::vector<std::thread> pool;
  startEach(pool, threads, [&](long k) {
    try {
      work(n * k / threads, n * (k + 1) / threads);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
    }
  });
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// Chunks of `chunk` items taken in turn by `threads` threads (0: all cores), the calling thread one of them; after
// each of its chunks the calling thread calls report(items done) (a Python progress callback must be called
// from there); an exception there (the user cancelled) stops the other threads at their next chunk and reaches
// the caller after the join, as one in another thread does.
template <class Work, class Report>
void parallelChunksReporting(long n, int threads, long chunk, Work&& work, Report&& report) {
  chunk = std::max<long>(1, chunk);
  threads = threadCount(threads);
  const long helpers = std::min<long>(threads, (n + chunk - 1) / chunk) - 1;
  std::atomic<long> next{0}, done{0};
  std::atomic<bool> stop{false};
  const auto takeChunk = [&] {
    const long from = stop ? n : next.fetch_add(chunk);
    if (from >= n) return false;
    const long to = std::min(n, from + chunk);
    work(from, to);
    done += to - from;
    return true;
  };
  std::exception_ptr failure;
  std::mutex mutex;
  std::vector<std::thread> pool;
  startEach(pool, helpers, [&](long) {
    try {
      while (takeChunk()) {
      }
    } catch (...) {
      stop = true;
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
    }
  });
  try {
    while (takeChunk()) report(done.load());
  } catch (...) {
    stop = true;
    for (auto& t : pool) t.join();
    throw;
  }
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// Calls work(from, to) over [0, n) in chunks of `chunk` items that `threads` threads (0: all cores) take in
// turn as they finish: the load balances itself where items cost unequally (a drop-cutter point over a dense
// region of the mesh costs several times one over a sparse one, so equal halves finish apart).
template <class Work>
void parallelChunks(long n, int threads, long chunk, Work&& work) {
  parallelChunksReporting(n, threads, chunk, std::forward<Work>(work), [](long) {});
}

}  // namespace hsm
