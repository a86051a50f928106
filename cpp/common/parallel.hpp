// Work split over threads in contiguous slices. An exception in a worker (an OCCT failure, a Cancelled)
// would end the process if it left the thread: it is kept and thrown again in the caller after the join.
#pragma once

#include "common/error.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
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

// Runs body(worker, stop, announce) on `workers` threads; each calls announce() after a piece of work and
// returns when its work is done or `stop` is set. Meanwhile the calling thread only reports: woken by each
// announce, it calls report(progress()) when that changes (a Python progress callback must be called from
// there), so it hears a cancel while the workers work, however long a piece takes. An exception there (the
// user cancelled) sets `stop` and reaches the caller after the join, as one in a worker does.
template <class Body, class Progress, class Report>
void superviseWorkers(long workers, Body&& body, Progress&& progress, Report&& report) {
  std::atomic<bool> stop{false};
  std::exception_ptr failure, cancelled;
  std::mutex mutex;
  std::condition_variable progressed;
  long finished = 0;  // workers that returned (under `mutex`)
  const auto announce = [&] {
    { const std::lock_guard<std::mutex> lock(mutex); }  // the reporter reads the progress under the lock
    progressed.notify_one();
  };
  std::vector<std::thread> pool;
  startEach(pool, workers, [&](long worker) {
    try {
      body(worker, stop, announce);
    } catch (...) {
      stop = true;
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
    }
    {
      const std::lock_guard<std::mutex> lock(mutex);
      ++finished;
    }
    progressed.notify_one();
  });
  {
    // Until the workers have returned and their last progress is reported (they may all be done before this
    // thread first looks).
    std::unique_lock<std::mutex> lock(mutex);
    long reported = 0;
    for (;;) {
      progressed.wait(lock, [&] { return finished == workers || progress() != reported; });
      const long now = progress();
      if (now == reported) {
        if (finished == workers) break;
        continue;
      }
      reported = now;
      if (cancelled) continue;
      lock.unlock();
      try {
        report(now);
      } catch (...) {
        stop = true;
        cancelled = std::current_exception();
      }
      lock.lock();
    }
  }
  for (auto& t : pool) t.join();
  if (cancelled) std::rethrow_exception(cancelled);
  if (failure) std::rethrow_exception(failure);
}

// Chunks of `chunk` items taken in turn by `threads` worker threads (0: all cores; one: the calling thread
// itself); after each chunk done the calling thread calls report(items done) (superviseWorkers: a cancel there
// stops the workers at their next chunk).
template <class Work, class Report>
void parallelChunksReporting(long n, int threads, long chunk, Work&& work, Report&& report) {
  chunk = std::max<long>(1, chunk);
  const long workers = std::min<long>(threadCount(threads), (n + chunk - 1) / chunk);
  if (workers <= 1) {
    for (long from = 0; from < n; from += chunk) {
      work(from, std::min(n, from + chunk));
      report(std::min(n, from + chunk));
    }
    return;
  }
  std::atomic<long> next{0}, done{0};
  superviseWorkers(
      workers,
      [&](long, const std::atomic<bool>& stop, const auto& announce) {
        for (long from = next.fetch_add(chunk); from < n && !stop; from = next.fetch_add(chunk)) {
          work(from, std::min(n, from + chunk));
          done += std::min(n, from + chunk) - from;
          announce();
        }
      },
      [&] { return done.load(); }, report);
}

// Calls work(lane, step) for every lane in [0, lanes) and every step in [0, steps), each lane's steps in order
// and never two of one lane at once, on `threads` threads (0: all cores; one: the calling thread itself): what
// a lane owns needs no lock, and no barrier holds the threads between steps. A thread takes the free lane that
// is furthest behind, among equals one of its own (lane % threads), so that a lane stays on one core while the
// cores keep pace and moves to another when one falls behind (other work on the machine, or a lane with more
// to do). A thread keeps a lane for up to `group` steps (no lock, no wake-up of the reporting thread
// between them: short steps cost more in hand-overs than in work otherwise). The calling thread calls
// report(steps every lane has done) as they advance (superviseWorkers: a cancel there stops the lanes at
// their next step).
template <class Work, class Report>
void parallelLanes(int lanes, int threads, long steps, Work&& work, Report&& report, long group = 1) {
  group = std::max<long>(1, group);
  lanes = std::max(1, lanes);
  const int workers = std::min(threadCount(threads), lanes);
  if (workers <= 1 || steps <= 0) {
    for (long step = 0; step < steps; ++step) {
      for (int lane = 0; lane < lanes; ++lane) work(lane, step);
      report(step + 1);
    }
    return;
  }
  std::mutex mutex;
  std::condition_variable freed;           // a lane was released, or the lanes must stop
  std::vector<std::atomic<long>> done(static_cast<size_t>(lanes));  // each lane's steps done
  std::vector<char> busy(static_cast<size_t>(lanes), 0);             // under `mutex`
  bool failed = false;                     // a step threw (under `mutex`)
  for (auto& d : done) d = 0;
  // The free lane furthest behind, one of `worker`'s among equals; -1 when none is free.
  const auto pick = [&](long worker) {
    int best = -1;
    for (int lane = 0; lane < lanes; ++lane) {
      if (busy[lane] || done[lane] >= steps) continue;
      if (best < 0 || done[lane] < done[best] || (done[lane] == done[best] && lane % workers == worker && best % workers != worker))
        best = lane;
    }
    return best;
  };
  superviseWorkers(
      workers,
      [&](long worker, const std::atomic<bool>& stop, const auto& announce) {
        std::unique_lock<std::mutex> lock(mutex);
        for (;;) {
          int lane = -1;
          freed.wait(lock, [&] {
            lane = pick(worker);
            const bool finished = std::all_of(done.begin(), done.end(), [&](const std::atomic<long>& d) { return d >= steps; });
            return lane >= 0 || finished || stop || failed;
          });
          if (lane < 0 || stop || failed) return;
          busy[lane] = 1;
          lock.unlock();
          try {
            for (long k = 0; k < group && done[lane] < steps && !stop; ++k) {
              work(lane, done[lane].load());
              ++done[lane];
            }
          } catch (...) {
            lock.lock();
            failed = true;
            freed.notify_all();
            throw;
          }
          lock.lock();
          busy[lane] = 0;
          freed.notify_all();
          lock.unlock();
          announce();
          lock.lock();
        }
      },
      [&] {
        long least = steps;
        for (const auto& d : done) least = std::min(least, d.load());
        return least;
      },
      report);
}

// Calls work(from, to) over [0, n) in chunks of `chunk` items that `threads` threads (0: all cores) take in
// turn as they finish: the load balances itself where items cost unequally (a drop-cutter point over a dense
// region of the mesh costs several times one over a sparse one, so equal halves finish apart).
template <class Work>
void parallelChunks(long n, int threads, long chunk, Work&& work) {
  parallelChunksReporting(n, threads, chunk, std::forward<Work>(work), [](long) {});
}

}  // namespace hsm
