/// @file parallel_for.h
/// @brief The one parallel loop of sim/ (and lungar-bake): body(i) for i in [0, n) on at most a given number of
///        threads. The first exception a body throws stops the other bodies and reaches the caller; a cancel flag
///        stops the loop between two bodies. Built on oneTBB; the caller never sees a TBB type.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <stdexcept>

namespace lungar::sim {

/// How a loop may run: on at most `threads` threads (0: every hardware thread), stopping once `*cancel` is true.
struct Workers {
  Workers() = default;
  /// A bare thread count converts, for the callers that have nothing to cancel.
  Workers(int thread_count, const std::atomic<bool>* cancel_flag = nullptr)  // NOLINT(google-explicit-constructor)
      : threads(thread_count), cancel(cancel_flag) {}
  int threads = 0;
  const std::atomic<bool>* cancel = nullptr;
};

/// Thrown by parallel_for and check_cancel once the cancel flag is set: the work was left unfinished.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

/// The threads a loop with `w` runs on: w.threads, but no more than the hardware has (all of them for 0).
int thread_count(const Workers& w);

/// Runs body(i) for every i in [0, n), in any order and at most thread_count(w) at once. When a body throws, the
/// bodies not yet started are skipped (and so are those of loops nested in this one), and the first exception is
/// rethrown here once the running ones have returned. When *w.cancel turns true, the loop stops likewise and
/// throws Cancelled. Bodies that each write their own output give the same results on any number of threads.
void parallel_for(std::size_t n, const Workers& w, const std::function<void(std::size_t i)>& body);

/// Inside a body: the index, in [0, thread_count(w)), of the thread running it; no two bodies of one loop that
/// run at the same time share it (per-thread scratch space), provided a body does not wait on a nested loop.
int worker_slot();

/// Inside a body: whether the thread that called parallel_for runs it (for a progress callback that must stay on
/// one thread).
bool on_calling_thread();

/// Throws Cancelled when *w.cancel is set: for the serial stages between loops.
void check_cancel(const Workers& w);

}  // namespace lungar::sim
