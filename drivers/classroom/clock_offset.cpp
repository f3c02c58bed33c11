/// @file clock_offset.cpp
/// @brief The clock filter: least-delay exchange of a sliding window, and the jitter about it.
#include "drivers/classroom/clock_offset.h"

#include <cmath>

namespace lungar::classroom {

namespace {
/// Both clocks tick in nanoseconds but are read at microsecond granularity by some kernels: a delay this
/// much below zero is rounding, not an impossible exchange.
constexpr std::int64_t kClockResolutionNs = 2'000;
}  // namespace

bool ClockOffsetEstimator::add(const ClockExchange& x) {
  if (x.t4_ns < x.t1_ns || x.t3_ns < x.t2_ns) return false;
  const std::int64_t delay = x.delay_ns();
  if (delay < -kClockResolutionNs || delay > kMaxDelayNs) return false;
  window_[next_] = x;
  next_ = (next_ + 1) % kWindow;
  if (count_ < kWindow) ++count_;
  return true;
}

std::optional<ClockEstimate> ClockOffsetEstimator::estimate() const {
  if (count_ == 0) return std::nullopt;
  std::size_t best = 0;
  for (std::size_t i = 1; i < count_; ++i) {
    if (window_[i].delay_ns() < window_[best].delay_ns()) best = i;
  }
  ClockEstimate e;
  e.offset_ns = window_[best].offset_ns();
  e.delay_ns = window_[best].delay_ns();
  e.samples = count_;
  double sum_sq = 0;
  for (std::size_t i = 0; i < count_; ++i) {
    const double d = static_cast<double>(window_[i].offset_ns() - e.offset_ns);
    sum_sq += d * d;
  }
  e.spread_ns = count_ > 1 ? std::sqrt(sum_sq / static_cast<double>(count_ - 1)) : 0.0;
  return e;
}

}  // namespace lungar::classroom
