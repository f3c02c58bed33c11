/// @file station_clock.h
/// @brief A station's clock for the classroom: CLOCK_REALTIME (what DDS stamps its source timestamps with), and
/// the mapping from the frame loop's monotonic clock onto it.
/// @ingroup platform
///
/// Stations on different PCs differ by whatever their wall clocks differ by; the trainee's offset estimate
/// absorbs it. A test can give a station a skew, as if its PC's clock were set wrong.
#pragma once

#include <cstdint>
#include <ctime>

#include "config/base/clock.h"

namespace lungar::classroom {

class StationClock {
 public:
  explicit StationClock(std::int64_t skew_ns = 0) : skew_ns_(skew_ns) {}

  /// Now on this station's clock, ns since the epoch.
  std::int64_t now_ns() const {
    timespec ts{};
    clock_gettime(CLOCK_REALTIME, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec + skew_ns_;
  }
  /// A monotonic_ns() reading on this station's clock (the two are read now, a few ns apart).
  std::int64_t from_monotonic(std::int64_t mono_ns) const { return mono_ns + (now_ns() - lungar::monotonic_ns()); }
  /// A station-clock time as a monotonic_ns() reading.
  std::int64_t to_monotonic(std::int64_t station_ns) const { return station_ns - (now_ns() - lungar::monotonic_ns()); }

 private:
  std::int64_t skew_ns_;
};

}  // namespace lungar::classroom
