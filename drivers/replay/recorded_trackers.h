/// @file recorded_trackers.h
/// @brief What a recorded log needs to be decoded again: the [trackers] it was recorded with, and the decoder of
///        its OpenIGTLink records. Shared by the replay, the PLUS conversion and the calibration's log reading.
/// @ingroup drivers
#pragma once

#include <string>

#include "config/base/result.h"
#include "drivers/igtl/igtl_decoder.h"
#include "drivers/replay/replay_interface.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/trk/trk_reader.h"

namespace lungar::drivers {

/// The [trackers] `log` was recorded with: its header's (every log lungar writes has one), else `otherwise`. An
/// error when the header does not load ("PATH (header layout):LINE: ...").
Result<TrackerConfig> recorded_trackers(const TrkLog& log, const std::string& path, const TrackerConfig& otherwise);

/// The decoder of a log's OpenIGTLink records, with `layout`'s names.
RecordDecoder igtl_record_decoder(IgtlLayout layout);

}  // namespace lungar::drivers
