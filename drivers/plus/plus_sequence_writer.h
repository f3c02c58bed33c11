/// @file plus_sequence_writer.h
/// @brief Writing PLUS tracked sequence files (`.igs.mha`): a session lungar recorded, opened in 3D Slicer (the
///        Sequences module) or replayed by PLUS like one of PlusServer's own. Each frame carries, per tool, the
///        `<Tool>ToTrackerTransform` (row-major 4 x 4, mm) and its status; a tool missing from a frame is written
///        INVALID with an identity matrix, as PLUS does. The image is a 1 x 1 placeholder per frame.
/// @ingroup drivers
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"
#include "drivers/plus/plus_sequence.h"
#include "drivers/pose/pose_sample.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/trk/trk_reader.h"

namespace lungar::drivers {

/// The whole file, header and placeholder pixels.
std::string plus_sequence_text(const PlusSequence& seq);

/// Writes `seq` to `path` atomically (all or nothing under that name).
Status write_plus_sequence(const std::string& path, const PlusSequence& seq);

/// The PLUS tool name of a role by `names` ([trackers.plus]), the one plus_tool_role() reads back: by default
/// Reference (the patient), HMD (the head), Stylus.
const std::string& plus_tool_of(Role role, const PlusConfig& names = {});

/// A recorded .trk log as a PLUS sequence: one frame per record that decodes, with the [trackers] it was recorded
/// with (its header's, else `otherwise`: its report layout, its OpenIGTLink names, its PLUS tool names), at its
/// arrival time from the first record, holding each tool seen so far (its role's PLUS name, relative to the
/// tracker) at its newest pose, INVALID once that is more than 0.1 s old. Records that do not decode are skipped and
/// counted in `skipped`.
Result<PlusSequence> plus_from_trk(const TrkLog& log, const std::string& path, const TrackerConfig& otherwise,
                                   int& skipped);

}  // namespace lungar::drivers
