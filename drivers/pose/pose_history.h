/// @file pose_history.h
/// @brief The last few samples of one role, and constant-velocity prediction from them.
/// @ingroup drivers
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "drivers/pose/pose_sample.h"

namespace lungar::drivers {

/// A fixed ring of the newest samples (oldest overwritten). Plain data, so it can be published whole.
struct PoseHistory {
  static constexpr std::size_t kCapacity = 16;
  std::array<PoseSample, kCapacity> ring{};
  std::uint32_t count = 0;  ///< valid entries, up to kCapacity
  std::uint32_t next = 0;   ///< where the next push goes

  void push(const PoseSample& s);
  /// The k-th newest sample (0 = newest); precondition k < count.
  const PoseSample& newest(std::size_t k = 0) const;
};

/// The pose extrapolated to monotonic time `t_ns` at constant linear and angular velocity, estimated from the
/// newest sample and one about `baseline_ns` older (device time). The lead is capped at `max_ahead_ns`; with
/// fewer than two samples the newest comes back unchanged. The result carries kPosePredicted when it moved.
PoseSample predict(const PoseHistory& h, std::int64_t t_ns, std::int64_t max_ahead_ns,
                   std::int64_t baseline_ns = 30'000'000);

}  // namespace lungar::drivers
