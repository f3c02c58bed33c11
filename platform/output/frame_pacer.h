/// @file frame_pacer.h
/// @brief display.max_fps for outputs that no swap interval paces (headless, a window without vsync): begin_frame
/// waits until the next frame's slot, so a headless classroom station does not burn a core drawing frames nobody
/// sees. 0 frames/s: unpaced.
/// @ingroup platform
#pragma once

#include <chrono>
#include <cstdint>
#include <thread>

#include "config/base/clock.h"

namespace lungar::platform {

class FramePacer {
 public:
  explicit FramePacer(double max_fps) : period_ns_(max_fps > 0 ? static_cast<std::int64_t>(1e9 / max_fps) : 0) {}

  /// Sleeps until this frame's slot (never when late or unpaced); returns the slot, or `now_ns` when unpaced.
  std::int64_t wait(std::int64_t now_ns) {
    if (period_ns_ == 0) return now_ns;
    next_ns_ = next_ns_ == 0 ? now_ns : next_ns_ + period_ns_;
    if (next_ns_ <= now_ns) {  // late: start again from now rather than hurry to catch up
      next_ns_ = now_ns;
      return now_ns;
    }
    std::this_thread::sleep_for(std::chrono::nanoseconds(next_ns_ - now_ns));
    return next_ns_;
  }

 private:
  std::int64_t period_ns_;
  std::int64_t next_ns_ = 0;
};

}  // namespace lungar::platform
