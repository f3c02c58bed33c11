/// @file log_histogram.h
/// @brief Percentiles of positive values in constant memory: a histogram with logarithmic buckets, so a run of
/// eight hours at display rate costs what a run of ten seconds does.
///
/// Buckets grow by 1 % from 1 us (1e-3 ms) to 1e5 ms; a percentile is the geometric centre of the bucket that
/// holds the nearest-rank value, so it is within 0.5 % of the value a sorted list would give (values outside the
/// range land in the end buckets and are reported as the exact minimum or maximum).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lungar {

class LogHistogram {
 public:
  static constexpr double kMin = 1e-3, kMax = 1e5, kGrowth = 1.01;
  static constexpr double kRelativeError = 0.005;             ///< of a percentile, for values in [kMin, kMax]
  static constexpr int kBuckets = 1852;                       ///< ceil(ln(kMax / kMin) / ln(kGrowth))
  static inline const double kLogGrowth = std::log(kGrowth);  ///< once, not at every add()

  /// Counts `value` (any finite number; values <= kMin share the first bucket). Allocates nothing.
  void add(double value) {
    if (!std::isfinite(value)) return;
    min_ = count_ ? std::min(min_, value) : value;
    max_ = count_ ? std::max(max_, value) : value;
    ++count_;
    sum_ += value;
    // Bucket index = floor(log_growth(value / kMin)).
    const double index = value > kMin ? std::floor(std::log(value / kMin) / kLogGrowth) : 0.0;
    counts_[static_cast<std::size_t>(std::clamp(index, 0.0, static_cast<double>(kBuckets - 1)))] += 1;
  }
  std::uint64_t count() const { return count_; }
  double min() const { return count_ ? min_ : 0.0; }
  double max() const { return count_ ? max_ : 0.0; }
  double mean() const { return count_ ? sum_ / static_cast<double>(count_) : 0.0; }
  /// The nearest-rank p-th percentile (p in 0..100); 0 when empty.
  double percentile(double p) const {
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

 private:
  std::array<std::uint64_t, kBuckets> counts_{};
  std::uint64_t count_ = 0;
  double min_ = 0, max_ = 0, sum_ = 0;
};

}  // namespace lungar
