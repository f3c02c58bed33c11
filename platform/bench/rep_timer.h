/// @file rep_timer.h
/// @brief Times a per-frame function: a warm-up, then repetitions of whole frames, each reduced to its mean; or two
/// functions interleaved, for their ratio.
#pragma once

#include <chrono>
#include <type_traits>
#include <vector>

#include "platform/bench/rep_stats.h"

namespace lungar::platform::bench {

struct Timing {
  int reps = 5;           ///< repetitions after the warm-up (the median is over these)
  double warmup_s = 0.3;  ///< frames run and discarded first (caches, driver state, first-use compilation)
  double rep_s = 0.3;     ///< each repetition runs whole frames until at least this long has passed
  int min_frames = 2;     ///< per repetition and warm-up, however slow the frame
};

/// Runs frame(k) with k = 0, 1, 2, ... (never reset, so time-varying inputs keep varying) in stretches of whole
/// frames; `frame` must finish its work (glFinish) before returning.
template <typename Frame>
class FrameLoop {
 public:
  FrameLoop(const Timing& t, Frame& frame) : t_(t), frame_(frame) {}
  /// Runs at least `seconds` (and Timing::min_frames frames); returns the mean frame time in ms.
  double run_for(double seconds) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    int n = 0;
    double elapsed = 0;
    while (n < t_.min_frames || elapsed < seconds) {
      frame_(k_++);
      ++n;
      elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    return elapsed * 1e3 / n;
  }
  long frames() const { return k_; }

 private:
  const Timing& t_;
  Frame& frame_;
  long k_ = 0;
};

/// A warm-up, then Timing::reps repetitions; the mean frame time of each.
template <typename Frame>
RepStats time_reps(const Timing& t, Frame&& frame, long* frames_run = nullptr) {
  FrameLoop<std::remove_reference_t<Frame>> loop(t, frame);
  loop.run_for(t.warmup_s);
  std::vector<double> reps;
  reps.reserve(static_cast<std::size_t>(t.reps));
  for (int r = 0; r < t.reps; ++r) reps.push_back(loop.run_for(t.rep_s));
  if (frames_run) *frames_run = loop.frames();
  return summarize(std::move(reps));
}

/// Two measurements interleaved repetition by repetition (a b, b a, a b, ...), so that a drift in the machine's
/// load falls on both: the ratio b / a of each pair of repetitions is what a ratio target should be judged by.
struct PairedStats {
  RepStats a, b;
  std::vector<double> ratios;  ///< b / a per repetition, in run order
  double ratio_median = 0;
};

template <typename A, typename B>
PairedStats time_reps_paired(const Timing& t, A&& a, B&& b) {
  FrameLoop<std::remove_reference_t<A>> la(t, a);
  FrameLoop<std::remove_reference_t<B>> lb(t, b);
  la.run_for(t.warmup_s);
  lb.run_for(t.warmup_s);
  std::vector<double> ta, tb;
  PairedStats p;
  for (int r = 0; r < t.reps; ++r) {
    double x = 0, y = 0;
    if (r % 2 == 0) {
      x = la.run_for(t.rep_s);
      y = lb.run_for(t.rep_s);
    } else {
      y = lb.run_for(t.rep_s);
      x = la.run_for(t.rep_s);
    }
    ta.push_back(x);
    tb.push_back(y);
    p.ratios.push_back(x > 0 ? y / x : 0.0);
  }
  p.ratio_median = median(p.ratios);
  p.a = summarize(std::move(ta));
  p.b = summarize(std::move(tb));
  return p;
}

}  // namespace lungar::platform::bench
