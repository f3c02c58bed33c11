/// @file rep_stats.cpp
/// @brief Median and range of repetition times.
#include "platform/bench/rep_stats.h"

#include <algorithm>

namespace lungar::platform::bench {

RepStats summarize(std::vector<double> reps_ms) {
  RepStats s;
  s.reps_ms = reps_ms;
  if (reps_ms.empty()) return s;
  std::sort(reps_ms.begin(), reps_ms.end());
  const std::size_t n = reps_ms.size();
  s.median_ms = n % 2 ? reps_ms[n / 2] : 0.5 * (reps_ms[n / 2 - 1] + reps_ms[n / 2]);
  s.min_ms = reps_ms.front();
  s.max_ms = reps_ms.back();
  return s;
}

}  // namespace lungar::platform::bench
