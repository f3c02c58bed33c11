/// @file decoder.h
/// @brief The pure report decoder: bytes + layout -> world-frame poses, or the reason the report is malformed.
/// @ingroup drivers
///
/// No state, no allocation, no I/O: the unit tests, the fuzz target and every source call this one function.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "drivers/decode/report_layout.h"

namespace lungar::drivers {

enum class DecodeError : std::uint8_t {
  None = 0,
  WrongLength,       ///< not exactly the layout's length
  UnknownReportId,   ///< first byte is not the layout's report id
  UnknownStation,    ///< station byte names no enabled sensor
  NotFinite,         ///< NaN or infinity in a field
  QuaternionNorm,    ///< |norm - 1| beyond the tolerance
  OutsideWorkspace,  ///< position outside the configured box
  TimeBackwards,     ///< device time ran backwards (reported by DeviceClock, not by decode_report)
  // OpenIGTLink messages (drivers/igtl):
  UnknownType,         ///< a message type lungar does not read (not TRANSFORM, TDATA or QTDATA)
  BadCrc,              ///< the body's CRC-64 differs from the header's
  Truncated,           ///< fewer bytes than the header announces (the sender stopped mid-message), or too many
  NotRigid,            ///< a transform whose rotation part is not orthonormal with determinant +1
  UnsupportedVersion,  ///< a header version other than 1 (OpenIGTLink 3's extended header)
};
inline constexpr int kDecodeErrorCount = 13;
const char* to_string(DecodeError e);

struct DecodedReport {
  DecodeError error = DecodeError::None;
  bool has_time = false;
  std::uint64_t device_ticks = 0;  ///< raw timestamp, time_bits wide
  int time_bits = 32;              ///< width of device_ticks (16, 32; 64 for OpenIGTLink's nanoseconds)
  double time_tick_ns = 1000.0;    ///< nanoseconds per tick
  int count = 0;                   ///< poses filled: role, position and (normalised) orientation in the world
  std::array<PoseSample, kRoleCount> poses{};
  /// Valid data for devices that feed no role (an OpenIGTLink device name not in [trackers.igtl]): not an error,
  /// not a pose. The first such name, NUL-terminated, for the log.
  int ignored = 0;
  std::array<char, 21> ignored_name{};
};

/// Tracker-frame position and unit-norm-within-tolerance orientation -> `out`'s world pose, or why not
/// (NotFinite, QuaternionNorm, OutsideWorkspace). The quaternion is normalised and given w >= 0.
DecodeError to_world(const Eigen::Vector3d& device_pos_mm, const Eigen::Quaterniond& q, const WorldFrame& w,
                     PoseSample& out);

/// Decodes one report. Every sensor of the report must be valid, or the whole report is rejected.
DecodedReport decode_report(std::span<const std::uint8_t> bytes, const ReportLayout& layout);

/// Unwraps a device timestamp of `bits` width (16, 32 or 64) into nanoseconds since the first report, and
/// rejects time that runs backwards (a step of more than half the counter's range reads as backwards, not as a
/// wrap).
class DeviceClock {
 public:
  /// Nanoseconds of device time, or -1 when `ticks` is older than the last accepted timestamp.
  std::int64_t advance(std::uint64_t ticks, int bits, double tick_ns);
  void reset() { started_ = false; }

 private:
  bool started_ = false;
  std::uint64_t last_ = 0;
  std::int64_t total_ticks_ = 0;
};

}  // namespace lungar::drivers
