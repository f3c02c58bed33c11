/// @file replay_interface.h
/// @brief Replays a .trk log's raw reports through the configured layout, at the recorded pace or at once.
/// @ingroup drivers
#pragma once

#include <memory>
#include <string>

#include "drivers/tracker/tracker_config.h"
#include "drivers/tracker/tracker_device.h"
#include "drivers/trk/trk_reader.h"

namespace lungar::drivers {

/// A source that feeds `log`'s records in order. `realtime`: keep the recorded spacing of arrival times;
/// otherwise as fast as the pipeline takes them. `loop`: start again at the end (else finish and go stale).
std::unique_ptr<TrackerDevice> replay_create(TrkLog log, const std::string& path, bool realtime, bool loop);

}  // namespace lungar::drivers
