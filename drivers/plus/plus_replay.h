/// @file plus_replay.h
/// @brief A PLUS tracked sequence as a replayable log: each valid transform of each frame becomes the OpenIGTLink
///        TRANSFORM message PlusServer would have sent for it, at the frame's time, so that the replay, the
///        OpenIGTLink decoder, the world frame and --record all work on it as on a live PlusServer.
/// @ingroup drivers
#pragma once

#include <optional>
#include <string>

#include "config/base/result.h"
#include "drivers/igtl/igtl_decoder.h"
#include "drivers/plus/plus_sequence.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/trk/trk_reader.h"

namespace lungar::drivers {

/// Which role a PLUS tool feeds by `names` ([trackers.plus]; PLUS's own by default: Reference, the marker on the
/// patient, the patient; Stylus or StylusTip the stylus; HMD or Head the head); none for another tool (not applied).
std::optional<Role> plus_tool_role(const std::string& tool, const PlusConfig& names = {});

struct PlusReplay {
  TrkLog log;              ///< OpenIGTLink records, one per valid transform of a role, frame by frame
  IgtlLayout layout;       ///< the transform names of the sequence, mapped to their roles
  int frames = 0;
  int invalid_skipped = 0;  ///< INVALID transforms of a role: skipped, never applied
  std::string describe;     ///< "N frames; Stylus -> stylus, Reference -> patient; K invalid transforms skipped"
};

/// The replay of `seq` with `settings`' world frame. Tools given relative to the Reference (StylusToReference) get
/// an identity patient pose in each frame, so that they are in the patient's frame as recorded. An error when no
/// tool feeds a role.
Result<PlusReplay> plus_replay(const PlusSequence& seq, const TrackerConfig& settings, const std::string& path);

}  // namespace lungar::drivers
