/// @file clock.h
/// @brief The one monotonic clock (the time base of pose arrival, frame timing and breathing) and wall-clock
/// stamps for logs and reports.
/// @ingroup base
#pragma once

#include <cstdint>
#include <ctime>
#include <string>

namespace lungar {

/// CLOCK_MONOTONIC in nanoseconds: never jumps with the wall clock, so ages and rates stay true.
inline std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

/// Seconds between two monotonic_ns() readings.
inline double seconds_between(std::int64_t from_ns, std::int64_t to_ns) {
  return static_cast<double>(to_ns - from_ns) * 1e-9;
}

/// The wall clock as "2026-11-23T15:36:02Z" (UTC), for reports and .trk headers.
inline std::string utc_timestamp() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  std::tm tm{};
  gmtime_r(&ts.tv_sec, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace lungar
