/// @file settings_load.h
/// @brief Reads [trackers] from TOML over the built-in defaults, rejecting anything it does not understand.
#pragma once

#include <string>

#include "config/base/result.h"
#include "config/settings.h"
#include "config/toml_section.h"

namespace lungar::config {

/// Reads [trackers] and its tables over `t`; throws ConfigError "FILE:LINE: key 'trackers.a': expected ..., got
/// ...". Unknown keys, wrong types, out-of-range values and inconsistent layouts are errors; nothing is clamped.
void read_tracker_settings(TomlSection s, TrackerSettings& t);

/// The [trackers] table of a TOML document (a .trk header's layout) over the defaults; `name` stands for the file.
/// The document's other tables belong to other readers and are not looked at.
Result<TrackerSettings> load_tracker_settings_from_string(const std::string& toml_text, const std::string& name);

/// The same from a config file (lungar-trk reads a profile's tracker part).
Result<TrackerSettings> load_tracker_settings(const std::string& path);

}  // namespace lungar::config
