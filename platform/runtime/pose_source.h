/// @file pose_source.h
/// @brief Where the frame's poses come from, behind one small interface (Monado's xrt_device plays this part):
/// a tracker thread (HID, OpenIGTLink, mock, replay), a teaching scenario turning the patient, or a classroom's
/// shared patient. The frame reads the newest pose per role and never knows which source it reads.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "drivers/pose/pose_sample.h"

namespace lungar::platform {

/// The counters every source keeps; the stats JSON's tracker_* keys.
struct SourceCounters {
  std::uint64_t reports = 0;     ///< reports or messages read, accepted or not
  std::uint64_t malformed = 0;   ///< dropped, never applied
  std::uint64_t reconnects = 0;  ///< times the device or server came back after being lost
  double rate_hz = 0;            ///< accepted samples per second over the run
  const char* state = "?";       ///< lower case, as in the stats JSON ("streaming", "stale", ...)
};

class PoseSource {
 public:
  virtual ~PoseSource() = default;
  /// One line for the start-up log ("hid /dev/hidraw0 (1234:5678 SN0001)", "replay FILE").
  virtual std::string describe() const = 0;
  /// The newest pose of `role`, flagged stale when older than the configured age at `now_ns`; an invalid
  /// sample before the first. Lock-free and allocation-free: the frame calls it.
  virtual drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const = 0;
  /// latest() extrapolated at constant velocity to `t_ns`, at most `max_ahead_ns` past the newest sample.
  virtual drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const = 0;
  /// The source's state for the status line ("streaming", "stale", "sync lost"); a literal, no allocation.
  virtual const char* state() const = 0;
  /// True once a finite source (a replay that does not loop) has delivered everything.
  virtual bool finished() const = 0;
  /// The counters over a run of `wall_s` seconds.
  virtual SourceCounters counters(double wall_s) const = 0;
  /// Adds the source's keys to the stats JSON: the tracker_* keys from counters(), and any of its own.
  virtual void add_stats(nlohmann::json& stats, double wall_s) const;
  /// Stops the source's threads; latest() keeps answering with the last poses.
  virtual void stop() = 0;
};

}  // namespace lungar::platform
