/// @file tracker.h
/// @brief The tracker API the frame loop uses: read the latest pose per role without locks, a short history for
/// prediction, counters and the connection state.
/// @ingroup drivers
///
/// A Tracker runs one device's thread (HID, mock, replay, OpenIGTLink: make_tracker() in
/// drivers/tracker_factory/ picks it from the config), which hands reports to the TrackerCore pipeline: decoded,
/// validated, accepted poses published; malformed reports are counted and never published.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "config/base/clock.h"
#include "config/base/result.h"
#include "drivers/decode/decoder.h"
#include "drivers/pose/pose_history.h"
#include "drivers/pose/pose_sample.h"

namespace lungar::drivers {

/// disconnected -> opening (found and opened, no report yet) -> streaming -> stale (no report for stale_ms)
/// -> streaming ...; a lost device goes back to disconnected.
enum class TrackerState : std::uint8_t { Disconnected, Opening, Streaming, Stale };
const char* to_string(TrackerState s);

/// For the stats JSON: tracker_reports, tracker_malformed, tracker_reconnects, tracker_rate_hz.
struct TrackerStats {
  std::uint64_t reports = 0;     ///< reports read, accepted or not
  std::uint64_t accepted = 0;    ///< reports decoded and published
  std::uint64_t malformed = 0;   ///< reports dropped (sum of malformed_by_reason)
  std::array<std::uint64_t, kDecodeErrorCount> malformed_by_reason{};  ///< indexed by DecodeError
  std::uint64_t opens = 0;       ///< times the device was opened (a HID device: opening until its first report)
  std::uint64_t reconnects = 0;  ///< times the device came back after being lost
  std::uint64_t recorded = 0;    ///< records written to the --record log
  std::uint64_t ignored = 0;     ///< valid data for devices that feed no role (OpenIGTLink names not configured)
  double rate_hz = 0;            ///< accepted reports per second over the last second (all sensors together)
  std::array<double, kRoleCount> role_rate_hz{};  ///< samples per second of each role, indexed by Role
  TrackerState state = TrackerState::Disconnected;
};

/// The time base of t_arrival_ns: config/base's one monotonic clock (CLOCK_MONOTONIC, nanoseconds).
using lungar::monotonic_ns;

struct TrackerOptions {
  std::string record_path;  ///< when set, every raw report read is appended to this .trk log
  /// One line per event (opened, lost, malformed reports at a limited rate); default: stderr with a timestamp.
  std::function<void(const std::string& line)> log;
  /// Called on the tracker thread for every accepted sample (tests, recording of poses); must not block.
  std::function<void(const PoseSample&)> on_sample;
  /// The [trackers] TOML for the .trk header (make_tracker() fills it: tracker_config_to_toml()).
  std::string record_layout_toml;
};

class TrackerCore;
class TrackerDevice;

class Tracker {
 public:
  /// Starts `device`'s thread feeding `core`.
  Tracker(std::unique_ptr<TrackerCore> core, std::unique_ptr<TrackerDevice> device);
  ~Tracker();  ///< stops and joins the thread
  Tracker(const Tracker&) = delete;
  Tracker& operator=(const Tracker&) = delete;

  /// The newest accepted pose of `role`, flagged kPoseStale when older than stale_ms at `now_ns`; a default
  /// (invalid) sample before the first. Lock-free; callable from any thread.
  PoseSample latest(Role role, std::int64_t now_ns) const;
  /// The newest samples of `role` (a copy, lock-free).
  PoseHistory history(Role role) const;
  /// latest() extrapolated at constant velocity to `t_ns`, at most `max_ahead_ns` past the newest sample.
  PoseSample predicted(Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const;
  TrackerStats stats() const;
  TrackerState state() const;
  /// True once a finite source (replay without loop) has delivered everything.
  bool finished() const;
  /// "mock upright_to_supine", "hid /dev/hidraw0 (1234:5678 SN0001)", "replay FILE" ...
  std::string describe() const;
  void stop();

 private:
  std::unique_ptr<TrackerCore> core_;
  std::unique_ptr<TrackerDevice> device_;
  struct Thread;
  std::unique_ptr<Thread> thread_;
};

}  // namespace lungar::drivers
