/// @file crc32.h
/// @brief CRC-32 (IEEE 802.3, reflected, as zlib and PNG use it) for the asset's per-section checksums.
#pragma once

#include <cstddef>
#include <cstdint>

namespace lungar::sim {

/// CRC-32 of `size` bytes, continuing from `crc` (0 to start).
std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace lungar::sim
