/// @file reopen_backoff.h
/// @brief When a device that is lost or cannot be opened is tried again: the policy the HID and the OpenIGTLink
/// devices share.
/// @ingroup drivers
#pragma once

#include <algorithm>
#include <cstdint>

namespace lungar::drivers {

/// The first try again comes trackers.reopen_backoff_ms after a loss; each failed try doubles the wait, up to
/// 4 s, so that an unplugged tracker costs a try every few seconds, not a busy loop. A device that opens starts
/// from the first wait again.
class ReopenBackoff {
 public:
  static constexpr std::int64_t kNsPerMs = 1'000'000;
  static constexpr std::int64_t kMaxWaitNs = 4000 * kNsPerMs;

  explicit ReopenBackoff(double first_ms) : first_ns_(static_cast<std::int64_t>(first_ms * kNsPerMs)) {}

  std::int64_t first_ns() const { return first_ns_; }
  long long first_ms() const { return static_cast<long long>(first_ns_ / kNsPerMs); }
  /// Whether a try is due at `now_ns` (at once before any failure or loss).
  bool due(std::int64_t now_ns) const { return now_ns >= next_ns_; }
  /// A try failed at `now_ns`: the next one waits the current wait, which then doubles.
  void failed(std::int64_t now_ns) {
    next_ns_ = now_ns + wait_ns_;
    wait_ns_ = std::min(wait_ns_ * 2, kMaxWaitNs);
  }
  /// The device opened: a later loss starts from the first wait.
  void opened() { wait_ns_ = first_ns_; }
  /// The open device was lost at `now_ns`: the next try comes after the first wait.
  void lost(std::int64_t now_ns) {
    wait_ns_ = first_ns_;
    next_ns_ = now_ns + wait_ns_;
  }

 private:
  std::int64_t first_ns_;
  std::int64_t wait_ns_ = first_ns_;
  std::int64_t next_ns_ = 0;
};

}  // namespace lungar::drivers
