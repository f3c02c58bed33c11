/// @file rep_stats.h
/// @brief Repetitions of one measurement reduced to what the tables show: the median and the spread.
#pragma once

#include <vector>

namespace lungar::platform::bench {

struct RepStats {
  std::vector<double> reps_ms;  ///< one mean frame time per repetition, in run order
  double median_ms = 0, min_ms = 0, max_ms = 0;
  double fps() const { return median_ms > 0 ? 1000.0 / median_ms : 0.0; }
};

/// The median of `values` (the mean of the two middle ones for an even count); 0 when empty.
double median(std::vector<double> values);

/// Median (mean of the two middle values for an even count), minimum and maximum of `reps_ms`; zeros when empty.
RepStats summarize(std::vector<double> reps_ms);

}  // namespace lungar::platform::bench
