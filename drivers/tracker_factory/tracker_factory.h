/// @file tracker_factory.h
/// @brief make_tracker(): the one place that names every tracker device (HID, OpenIGTLink, mock, replay) and
/// builds the one the config picks, as Monado's targets assemble its drivers; the devices never include each
/// other, and the pipeline (drivers/tracker/) knows none of them.
/// @ingroup drivers
#pragma once

#include <memory>

#include "config/base/result.h"
#include "drivers/tracker/tracker.h"
#include "drivers/tracker/tracker_config.h"

namespace lungar::drivers {

/// Builds the device named by settings.source (mock | hid | replay | igtl) and starts its thread. A HID tracker
/// that is not plugged in, or an OpenIGTLink server that is not up, is not an error: it starts disconnected and
/// connects when the device or server appears. An error is one line naming what is wrong (layout, replay file,
/// record file).
Result<std::unique_ptr<Tracker>> make_tracker(const TrackerConfig& settings, const TrackerOptions& options = {});

}  // namespace lungar::drivers
