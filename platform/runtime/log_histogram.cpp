/// @file log_histogram.cpp
/// @brief Bucket index = floor(log_growth(value / kMin)).
#include "platform/runtime/log_histogram.h"

#include <algorithm>
#include <cmath>

namespace lungar::platform {

namespace {
const double kLogGrowth = std::log(LogHistogram::kGrowth);
}

void LogHistogram::add(double value) {
  if (!std::isfinite(value)) return;
  min_ = count_ ? std::min(min_, value) : value;
  max_ = count_ ? std::max(max_, value) : value;
  ++count_;
  sum_ += value;
  const double index = value > kMin ? std::floor(std::log(value / kMin) / kLogGrowth) : 0.0;
  counts_[static_cast<std::size_t>(std::clamp(index, 0.0, static_cast<double>(kBuckets - 1)))] += 1;
}

double LogHistogram::percentile(double p) const {
  if (count_ == 0) return 0.0;
  const double rank = std::max(1.0, std::ceil(p / 100.0 * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (int b = 0; b < kBuckets; ++b) {
    seen += counts_[static_cast<std::size_t>(b)];
    if (static_cast<double>(seen) < rank) continue;
    // The end buckets also hold the values outside the range: those are the exact minimum or maximum.
    if (b == 0 && min_ < kMin) return min_;
    if (b == kBuckets - 1 && max_ > kMax) return max_;
    return std::clamp(kMin * std::pow(kGrowth, b + 0.5), min_, max_);  // the bucket's geometric centre
  }
  return max_;
}

}  // namespace lungar::platform
