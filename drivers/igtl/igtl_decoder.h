/// @file igtl_decoder.h
/// @brief The pure OpenIGTLink decoder: one message's bytes (header + body) + layout -> world-frame poses, or
/// the reason the message is dropped.
/// @ingroup drivers
///
/// No state, no allocation, no I/O, like decode_report(): the live source, replay of a recorded .trk, `lungar-trk
/// dump`, the unit tests and the fuzz target all call this one function, so replay is bit-identical to live.
/// The wire format is the library's (libopenigtlink 1.11, protocol version 2): its header struct, byte-order
/// conversions and CRC-64; TRANSFORM, TDATA and QTDATA bodies are read, every other type is dropped.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "config/base/result.h"
#include "drivers/decode/decoder.h"
#include "drivers/decode/report_settings.h"
#include "drivers/igtl/igtl_settings.h"

namespace lungar::drivers {

/// Bytes of an OpenIGTLink (version 1) header; the body follows.
inline constexpr std::size_t kIgtlHeaderBytes = 58;
/// The longest body lungar reads (the .trk record limit less the header): TDATA with 57 tools, QTDATA with 80.
inline constexpr std::size_t kIgtlMaxBody = 4096 - kIgtlHeaderBytes;

/// What decode_igtl_message() needs, resolved from [trackers.igtl] and [trackers]: plain data.
struct IgtlLayout {
  /// The device (TRANSFORM) or tool (TDATA, QTDATA) name feeding each role, NUL-padded; empty: not fed.
  std::array<std::array<char, 21>, kRoleCount> device{};
  double scale = 1.0;             ///< mm per received unit
  double rigid_tolerance = 1e-3;  ///< max |R^T R - I| entry of an accepted rotation
  WorldFrame world;
};
Result<IgtlLayout> make_igtl_layout(const IgtlConfig& igtl, const LayoutConfig& world);

/// What the reader needs from a header before it reads the body.
struct IgtlHeaderInfo {
  std::uint64_t body_size = 0;
  bool readable = false;  ///< version 1 and a type decode_igtl_message() reads: worth buffering the body
};
IgtlHeaderInfo igtl_header_info(std::span<const std::uint8_t, kIgtlHeaderBytes> header);

/// Decodes one message: header, then its whole body. Time: the header's timestamp (seconds and 2^-32 fractions)
/// as 64-bit nanoseconds, or none when the sender leaves it 0. Every tool of a TDATA / QTDATA message must be
/// valid, or the whole message is rejected; tools and devices that feed no role are counted in `ignored`.
DecodedReport decode_igtl_message(std::span<const std::uint8_t> bytes, const IgtlLayout& layout);

}  // namespace lungar::drivers
