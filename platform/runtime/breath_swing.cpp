/// @file breath_swing.cpp
/// @brief The ring and its spread.
#include "platform/runtime/breath_swing.h"

#include <algorithm>

namespace lungar::platform {

void BreathSwing::add(std::int64_t now_ns, double dv_ml) {
  // One sample a step: a breath's extremes move slowly, so 20 ms loses under 0.1 % of the swing.
  if (count_ > 0 && now_ns - at_[(next_ + kSamples - 1) % kSamples] < kStepNs) return;
  dv_[next_] = dv_ml;
  at_[next_] = now_ns;
  next_ = (next_ + 1) % kSamples;
  count_ = std::min(count_ + 1, kSamples);
}

double BreathSwing::swing_ml() const {
  if (count_ < 2) return 0.0;
  const std::int64_t newest = at_[(next_ + kSamples - 1) % kSamples];
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < count_; ++i) {
    if (newest - at_[i] > kWindowNs) continue;
    lo = std::min(lo, dv_[i]);
    hi = std::max(hi, dv_[i]);
  }
  return hi > lo ? hi - lo : 0.0;
}

}  // namespace lungar::platform
