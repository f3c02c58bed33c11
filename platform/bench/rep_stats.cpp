/// @file rep_stats.cpp
/// @brief Median and range of repetition times.
#include "platform/bench/rep_stats.h"

#include <algorithm>

namespace lungar::platform::bench {

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

RepStats summarize(std::vector<double> reps_ms) {
  RepStats s;
  s.reps_ms = reps_ms;
  if (reps_ms.empty()) return s;
  s.median_ms = median(reps_ms);
  s.min_ms = *std::min_element(reps_ms.begin(), reps_ms.end());
  s.max_ms = *std::max_element(reps_ms.begin(), reps_ms.end());
  return s;
}

}  // namespace lungar::platform::bench
