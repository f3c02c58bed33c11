/// @file breath_swing.h
/// @brief The volume swing of the last breath, for the ventilation map: the spread of dV over the last few
///        seconds (a breath at 6 to 60 a minute fits), from samples kept at most every 20 ms in a fixed ring, so
///        that a fast GPU's thousand frames a second neither grow it nor shorten the window.
#pragma once

#include <array>
#include <cstdint>

namespace lungar::platform {

class BreathSwing {
 public:
  static constexpr std::int64_t kWindowNs = 10'000'000'000;  ///< the slowest breath the map follows: 6 a minute
  static constexpr std::int64_t kStepNs = 20'000'000;
  static constexpr std::size_t kSamples = kWindowNs / kStepNs;

  /// Records dV at `now_ns` (monotonic).
  void add(std::int64_t now_ns, double dv_ml);
  /// max - min of dV over the window, mL (0 before two samples).
  double swing_ml() const;

 private:
  std::array<double, kSamples> dv_{};
  std::array<std::int64_t, kSamples> at_{};
  std::size_t next_ = 0, count_ = 0;
};

}  // namespace lungar::platform
