/// @file clock_offset.h
/// @brief The instructor's clock seen from a trainee: an NTP-style offset estimate from request/reply exchanges
/// stamped with DDS source timestamps (RFC 5905's on-wire calculation and clock filter, much simplified).
/// @ingroup platform
///
/// One exchange: the trainee sends at t1 (its clock, the request's source timestamp), the instructor receives
/// at t2 and replies at t3 (its clock, the reply's source timestamp), the trainee receives at t4. With a
/// symmetric path, offset theta = ((t2 - t1) + (t3 - t4)) / 2 and round-trip delay delta = (t4 - t1) - (t3 - t2);
/// theta's error is at most delta / 2. Of the last kWindow exchanges the one with the least delay is the best
/// estimate (NTP's clock filter), and the spread is the RMS of the others' offsets about it (NTP's jitter).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace lungar::classroom {

/// The four timestamps of one exchange, ns.
struct ClockExchange {
  std::int64_t t1_ns = 0, t2_ns = 0, t3_ns = 0, t4_ns = 0;
  std::int64_t offset_ns() const { return ((t2_ns - t1_ns) + (t3_ns - t4_ns)) / 2; }
  std::int64_t delay_ns() const { return (t4_ns - t1_ns) - (t3_ns - t2_ns); }
};

struct ClockEstimate {
  std::int64_t offset_ns = 0;  ///< instructor clock minus trainee clock
  std::int64_t delay_ns = 0;   ///< round trip of the exchange it comes from
  double spread_ns = 0;        ///< RMS of the window's offsets about offset_ns
  std::size_t samples = 0;     ///< exchanges in the window
};

class ClockOffsetEstimator {
 public:
  static constexpr std::size_t kWindow = 16;
  /// An exchange whose delay exceeds this is not a network path but a stall (a descheduled process): ignored.
  static constexpr std::int64_t kMaxDelayNs = 200'000'000;

  /// Adds an exchange; false (and ignored) when its timestamps are impossible (negative delay beyond the
  /// clocks' resolution, t4 before t1, t3 before t2) or its delay is a stall.
  bool add(const ClockExchange& x);
  /// The estimate, or nothing before the first exchange.
  std::optional<ClockEstimate> estimate() const;
  /// Forgets every exchange (the instructor restarted: its clock may be another).
  void reset() {
    count_ = 0;
    next_ = 0;
  }

 private:
  std::array<ClockExchange, kWindow> window_{};
  std::size_t count_ = 0;
  std::size_t next_ = 0;
};

}  // namespace lungar::classroom
