/// @file plus_recording.h
/// @brief `--record FILE.igs.mha`: a session recorded as a PLUS tracked sequence, to open in 3D Slicer. The tracker
/// records its crash-tolerant .trk log beside it while the session runs (FILE.igs.mha.trk: what a crash leaves is
/// still a readable log); when the session ends the log becomes FILE.igs.mha, written whole, and goes.
/// @ingroup platform
#pragma once

#include <string>

#include "config/base/result.h"
#include "drivers/tracker/tracker_config.h"

namespace lungar::platform {

/// The .trk the tracker should write for `record_path`: itself, or FILE.igs.mha.trk for a PLUS sequence.
std::string tracker_record_path(const std::string& record_path);

/// For a PLUS `record_path`: the session's .trk as FILE.igs.mha (its OpenIGTLink records decoded with `trackers`'
/// names), the .trk removed once that is written. A line saying what was written, or the error (the .trk is kept).
Result<std::string> finish_plus_recording(const std::string& record_path, const drivers::TrackerConfig& trackers);

}  // namespace lungar::platform
