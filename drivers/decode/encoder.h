/// @file encoder.h
/// @brief The decoder's inverse: world-frame poses -> the bytes a device with this layout would send.
/// @ingroup drivers
///
/// The mock source and `lungar-trk synth` make raw reports with it, so that everything downstream (recording,
/// replay, the decoder) runs on the same bytes as with a real tracker.
#pragma once

#include <cstdint>
#include <span>

#include "drivers/decode/decoder.h"

namespace lungar::drivers {

/// Fills `out` (at least layout.length bytes; the rest is untouched) with one report carrying `poses`, stamped
/// with `ticks`. With a station byte, exactly one pose per report. Unused bytes are zero. Values beyond a
/// field's range saturate. Returns false when a pose's role has no sensor, or `out` is too short.
bool encode_report(const ReportLayout& layout, std::span<const PoseSample> poses, std::uint32_t ticks,
                   std::span<std::uint8_t> out);

}  // namespace lungar::drivers
