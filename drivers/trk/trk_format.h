/// @file trk_format.h
/// @brief The .trk tracker log: a self-describing header, then one CRC-guarded record per raw report.
/// @ingroup drivers
///
/// Little-endian throughout.
///   header : magic "LUNGATRK" (8) | version u32 (= 1) | description length u32 | description (UTF-8
///            "key=value" lines: vendor_id, product_id, serial, product, path, source) | layout length u32 |
///            layout (the TOML [trackers...] tables that describe the reports) | CRC-32 u32 of all before it
///   record : sync u16 (0x4B52) | source u8 (TrkSource) | reserved u8 | length u16 | t_arrival_ns u64
///            (CLOCK_MONOTONIC) |
///            report bytes | CRC-32 u32 of source .. report bytes
/// A record is written with one write() on an O_APPEND descriptor, so a crash loses at most the last record,
/// and the reader treats a short tail as the end of the log.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace lungar::drivers {

inline constexpr char kTrkMagic[8] = {'L', 'U', 'N', 'G', 'A', 'T', 'R', 'K'};
inline constexpr std::uint32_t kTrkVersion = 1;
inline constexpr std::uint16_t kTrkSync = 0x4B52;
inline constexpr std::size_t kTrkRecordOverhead = 2 + 1 + 1 + 2 + 8 + 4;
inline constexpr std::size_t kTrkMaxReport = 4096;  ///< hidraw's largest report
inline constexpr std::size_t kTrkMaxText = 1 << 20;  ///< bound on description and layout texts

/// Where a record's bytes came from, and so how they decode: Hid, Mock, Synth and Replay records hold one HID
/// report (decoded with [trackers.report]); Igtl records hold one OpenIGTLink message as it arrived, header and
/// body (decoded by decode_igtl_message() with [trackers.igtl]), whichever source fed them.
enum class TrkSource : std::uint8_t { Hid = 0, Mock = 1, Synth = 2, Replay = 3, Igtl = 4 };
const char* to_string(TrkSource s);

struct TrkHeader {
  std::uint32_t version = kTrkVersion;
  std::string description;  ///< "key=value" lines
  std::string layout_toml;  ///< TOML with the [trackers...] tables for the recorded device ("" if unknown)
  std::size_t size = 0;     ///< bytes the header takes in the file (set by the reader)

  /// The value of `key` in the description, "" when absent.
  std::string field(const std::string& key) const;
};

/// One record as it lies in the file (the span points into the caller's buffer).
struct TrkRecord {
  TrkSource source = TrkSource::Hid;
  std::int64_t t_arrival_ns = 0;
  std::span<const std::uint8_t> report;
};

}  // namespace lungar::drivers
