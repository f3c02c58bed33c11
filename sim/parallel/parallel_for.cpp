/// @file parallel_for.cpp
/// @brief parallel_for on oneTBB. Why TBB: a well-kept work-stealing pool instead of our own, task arenas that cap
///        the threads, and group cancellation, so that a body's exception reaches the caller and stops the rest.
#include "sim/parallel/parallel_for.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>

namespace lungar::sim {
namespace {

/// One running loop: whether it stops, its first exception, and the loop whose body called it (a nested loop
/// stops with its parent, which TBB's own cancellation does not carry into another arena).
class Loop {
 public:
  Loop(const std::atomic<bool>* cancel, const Loop* parent) : cancel_(cancel), parent_(parent) {}

  const std::thread::id caller = std::this_thread::get_id();

  /// This loop, or one it is nested in, has failed or been cancelled.
  bool stopping() const {
    for (const Loop* l = this; l != nullptr; l = l->parent_) {
      if (l->stopped_.load(std::memory_order_relaxed)) return true;
      if (l->cancel_ != nullptr && l->cancel_->load(std::memory_order_relaxed)) return true;
    }
    return false;
  }
  /// Keeps the first exception (later ones, often Cancelled from the bodies it stopped, are dropped).
  void fail(std::exception_ptr e) {
    const std::lock_guard lock(mutex_);
    if (!first_) first_ = std::move(e);
    stopped_.store(true, std::memory_order_relaxed);
  }
  void rethrow_first() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  const std::atomic<bool>* cancel_;
  const Loop* parent_;
  std::atomic<bool> stopped_{false};
  std::mutex mutex_;
  std::exception_ptr first_;
};

/// The loop and slot of the body this thread is running (none outside a body).
thread_local const Loop* t_loop = nullptr;
thread_local int t_slot = 0;

/// Makes `loop` and `slot` this thread's while a chunk of bodies runs; restores the outer ones after.
class InBody {
 public:
  InBody(const Loop& loop, int slot) : loop_(t_loop), slot_(t_slot) {
    t_loop = &loop;
    t_slot = slot;
  }
  ~InBody() {
    t_loop = loop_;
    t_slot = slot_;
  }
  InBody(const InBody&) = delete;
  InBody& operator=(const InBody&) = delete;

 private:
  const Loop* loop_;
  int slot_;
};

/// Bodies [first, last) on this thread, until the loop stops; false once it has.
bool run_chunk(Loop& loop, int slot, std::size_t first, std::size_t last,
               const std::function<void(std::size_t)>& body) {
  const InBody scope(loop, slot);
  for (std::size_t i = first; i < last; ++i) {
    if (loop.stopping()) {
      loop.fail(std::make_exception_ptr(Cancelled()));
      return false;
    }
    try {
      body(i);
    } catch (...) {
      loop.fail(std::current_exception());
      return false;
    }
  }
  return true;
}

}  // namespace

int thread_count(const Workers& w) {
  // More would not run at once anyway: TBB's pool has one thread a core (and warns when asked for more).
  const int hardware = std::max(1, tbb::info::default_concurrency());
  return w.threads > 0 ? std::min(w.threads, hardware) : hardware;
}

void parallel_for(std::size_t n, const Workers& w, const std::function<void(std::size_t i)>& body) {
  if (n == 0) return;
  Loop loop(w.cancel, t_loop);
  const int threads = thread_count(w);
  if (threads == 1 || n == 1) {
    run_chunk(loop, 0, 0, n, body);
  } else {
    tbb::task_group_context group;
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
        if (!run_chunk(loop, tbb::this_task_arena::current_thread_index(), r.begin(), r.end(), body))
          group.cancel_group_execution();  // the chunks not yet started are skipped
      }, group);
    });
  }
  loop.rethrow_first();
}

int worker_slot() { return t_slot; }

bool on_calling_thread() { return t_loop != nullptr && t_loop->caller == std::this_thread::get_id(); }

void check_cancel(const Workers& w) {
  if (w.cancel != nullptr && w.cancel->load(std::memory_order_relaxed)) throw Cancelled();
}

}  // namespace lungar::sim
