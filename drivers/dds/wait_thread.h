/// @file wait_thread.h
/// @brief The thread a DDS reader loop runs on, stopped by waking the waitset it waits on: the classroom's stations
///        and the physiology readers each own one.
#pragma once

#include <atomic>
#include <thread>
#include <utility>

#include "drivers/dds/dds.h"

namespace lungar::dds {

/// The thread a reader loop runs on: a classroom station's sync loop, a physiology reader's. Neither copied nor
/// moved (its atomic flag and thread are not). stop() sets the flag its loop checks, wakes the waitset the loop waits
/// on and joins; the owner calls it before the members the loop uses go (and it is the owner's last member, so that
/// its own destructor, which stops it too, runs first).
class WaitThread {
 public:
  ~WaitThread() { stop(); }

  /// Runs `loop` on a new thread; the loop waits on `waitset` and returns once stopping() is true.
  template <class F>
  void start(WaitSet& waitset, F&& loop) {
    waitset_ = &waitset;
    thread_ = std::thread(std::forward<F>(loop));
  }
  bool stopping() const { return stop_.load(); }
  void stop() {
    stop_.store(true);
    if (waitset_) waitset_->trigger();
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::atomic<bool> stop_{false};
  WaitSet* waitset_ = nullptr;
  std::thread thread_;
};

}  // namespace lungar::dds
