/// @file tracker_core.h
/// @brief The pipeline every device feeds: raw report -> record -> decode -> validate -> publish, with counters.
/// @ingroup drivers
///
/// It knows no device: reports in the configured layout ([trackers.report]) it decodes itself; a device with a
/// protocol of its own (OpenIGTLink) decodes its messages and hands over the poses with the bytes to record.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <string>

#include "drivers/decode/decoder.h"
#include "drivers/pose/mailbox.h"
#include "drivers/tracker/tracker.h"
#include "drivers/trk/trk_writer.h"

namespace lungar::drivers {

class TrackerCore {
 public:
  TrackerCore(const ReportLayout& layout, double stale_ms, TrackerOptions options);

  /// Opens the --record log with the device's description in its header.
  Status start_recording(const std::string& path, const std::string& description, TrkSource source);

  /// One raw report read at `t_arrival_ns` (monotonic). Records it, decodes it, and publishes its poses or
  /// counts why not. Allocates nothing (unless a callback or the rate-limited log does).
  DecodeError feed(std::span<const std::uint8_t> report, std::int64_t t_arrival_ns);
  /// The same for bytes a device decoded itself (an OpenIGTLink message, or what arrived of it): recorded as
  /// `source`, the value replay knows their decoder by, then `decoded` is validated and published as feed() does.
  DecodeError feed_decoded(TrkSource source, std::span<const std::uint8_t> bytes, const DecodedReport& decoded,
                           std::int64_t t_arrival_ns);

  /// Between reads: streaming -> stale after stale_ms without an accepted report; the rate decays to 0.
  void tick(std::int64_t now_ns);
  void set_state(TrackerState s);
  /// The device came back: counts it and restarts the device clock.
  void count_reconnect();
  /// The device clock may restart (a replug, a replay loop): device time continues from the last sample.
  void restart_device_clock();
  /// The device was opened (stats().opens).
  void count_open() { opens_.fetch_add(1, std::memory_order_relaxed); }
  void set_finished() { finished_.store(true, std::memory_order_release); }

  /// One log line, "drivers: " prefixed; `key` groups lines for rate limiting (-1: never limited).
  void log(int key, const char* fmt, ...) __attribute__((format(printf, 3, 4)));

  PoseSample latest(Role role, std::int64_t now_ns) const;
  PoseHistory history(Role role) const { return history_mail_[static_cast<std::size_t>(role)].read(); }
  TrackerStats stats() const;
  TrackerState state() const { return state_.load(std::memory_order_acquire); }
  bool finished() const { return finished_.load(std::memory_order_acquire); }
  const ReportLayout& layout() const { return layout_; }
  std::int64_t stale_ns() const { return stale_ns_; }
  TrkSource record_source = TrkSource::Hid;

 private:
  void record(TrkSource source, std::span<const std::uint8_t> bytes, std::int64_t t_arrival_ns);
  DecodeError accept(const DecodedReport& d, std::size_t bytes, std::int64_t t_arrival_ns);

  const ReportLayout layout_;
  const std::int64_t stale_ns_;
  TrackerOptions options_;
  TrkWriter recorder_;
  bool recording_ = false;

  // Written by the tracker thread only.
  DeviceClock clock_;
  bool rebase_ = false;
  std::int64_t device_base_ns_ = 0;
  std::int64_t last_device_ns_ = -1;
  std::int64_t last_arrival_ns_ = 0;
  std::int64_t rate_window_start_ns_ = 0;
  std::uint64_t rate_window_count_ = 0;
  std::array<std::uint64_t, kRoleCount> role_window_count_{};
  std::array<PoseHistory, kRoleCount> history_{};
  std::array<std::int64_t, 16> log_last_ns_{};
  std::array<std::uint64_t, 16> log_suppressed_{};

  // Read by any thread.
  std::array<LatestMailbox<PoseSample>, kRoleCount> latest_;
  std::array<LatestMailbox<PoseHistory>, kRoleCount> history_mail_;
  std::atomic<std::uint64_t> reports_{0}, accepted_{0}, opens_{0}, reconnects_{0}, recorded_{0}, ignored_{0};
  std::array<std::atomic<std::uint64_t>, kDecodeErrorCount> malformed_{};
  std::atomic<std::int64_t> last_accepted_ns_{0};
  std::atomic<double> rate_hz_{0};
  std::array<std::atomic<double>, kRoleCount> role_rate_hz_{};
  std::atomic<TrackerState> state_{TrackerState::Disconnected};
  std::atomic<bool> finished_{false};
};

}  // namespace lungar::drivers
