/// @file rep_timer.h
/// @brief Times a per-frame function: a warm-up, then repetitions of whole frames, each reduced to its mean.
#pragma once

#include <chrono>
#include <vector>

#include "platform/bench/rep_stats.h"

namespace lungar::platform::bench {

struct Timing {
  int reps = 5;            ///< repetitions after the warm-up (the median is over these)
  double warmup_s = 0.3;   ///< frames run and discarded first (caches, driver state, first-use compilation)
  double rep_s = 0.3;      ///< each repetition runs whole frames until at least this long has passed
  int min_frames = 2;      ///< per repetition and warm-up, however slow the frame
};

/// Calls frame(k) with k = 0, 1, 2, ... (never reset, so time-varying inputs keep varying) and returns the mean
/// frame time of each repetition. `frame` must finish its work (glFinish) before returning.
template <typename Frame>
RepStats time_reps(const Timing& t, Frame&& frame, long* frames_run = nullptr) {
  using Clock = std::chrono::steady_clock;
  long k = 0;
  auto run_for = [&](double seconds) {
    const auto t0 = Clock::now();
    int n = 0;
    double elapsed = 0;
    while (n < t.min_frames || elapsed < seconds) {
      frame(k++);
      ++n;
      elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    return elapsed * 1e3 / n;
  };
  run_for(t.warmup_s);
  std::vector<double> reps;
  reps.reserve(static_cast<std::size_t>(t.reps));
  for (int r = 0; r < t.reps; ++r) reps.push_back(run_for(t.rep_s));
  if (frames_run) *frames_run = k;
  return summarize(std::move(reps));
}

}  // namespace lungar::platform::bench
