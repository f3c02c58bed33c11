/// @file layout_toml.h
/// @brief Writes the report-layout part of the tracker settings back as TOML, for .trk headers: a log names
/// the layout its bytes were made with, and load_tracker_settings_from_string() reads it back.
#pragma once

#include <string>

#include "config/base/result.h"
#include "config/settings.h"

namespace lungar::drivers {

/// [trackers] (axis_remap, world_offset_mm, workspace, tolerance), [trackers.report], the sensor tables and
/// [trackers.igtl] (device names, scale, rigidity tolerance).
std::string layout_to_toml(const config::TrackerSettings& t);

/// The tracker settings described by a .trk header's layout text, or why it does not load.
Result<config::TrackerSettings> layout_from_toml(const std::string& toml, const std::string& name);

}  // namespace lungar::drivers
