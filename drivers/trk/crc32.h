/// @file crc32.h
/// @brief CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), as zlib computes it; guards .trk records.
#pragma once

#include <cstdint>
#include <span>

namespace lungar::drivers {

/// CRC of `bytes`, continuing from `crc` (0 to start).
std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0);

}  // namespace lungar::drivers
