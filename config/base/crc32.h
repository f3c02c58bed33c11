/// @file crc32.h
/// @brief CRC-32 (IEEE 802.3, reflected 0xEDB88320) through zlib, which libpng already brings: it guards the
/// baked asset's sections and the .trk log's records.
/// @ingroup base
#pragma once

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace lungar {

/// CRC of `size` bytes at `data`, continuing from `crc` (0 to start).
inline std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0) {
  const auto* bytes = static_cast<const Bytef*>(data);
  uLong c = crc;
  while (size > 0) {  // zlib takes a uInt length: feed very large buffers in pieces
    const auto piece = static_cast<uInt>(size < std::numeric_limits<uInt>::max() ? size : std::numeric_limits<uInt>::max());
    c = ::crc32(c, bytes, piece);
    bytes += piece;
    size -= piece;
  }
  return static_cast<std::uint32_t>(c);
}

/// The same over a span of bytes (the .trk reader and writer).
inline std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0) {
  return crc32(bytes.data(), bytes.size(), crc);
}

}  // namespace lungar
