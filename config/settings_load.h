/// @file settings_load.h
/// @brief Loads settings from TOML over the built-in defaults, rejecting anything it does not understand.
#pragma once

#include <optional>
#include <string>

#include "config/base/result.h"
#include "config/settings.h"

namespace lungar::config {

/// Reads `path` and overlays it on the defaults; an error is one line: "FILE:LINE: key 'a.b': expected ..., got ...". Unknown keys, wrong types, out-of-range values and
/// syntax errors are errors; nothing is clamped.
Result<Settings> load_settings(const std::string& path);

/// The same from TOML text; `name` stands for the file in messages.
Result<Settings> load_settings_from_string(const std::string& toml_text, const std::string& name);

/// A one-paragraph human summary of the settings, for start-up logs.
std::string summarize(const Settings& s);

}  // namespace lungar::config
