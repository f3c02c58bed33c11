/// @file settings_load.h
/// @brief Loads settings from TOML over the built-in defaults, rejecting anything it does not understand.
#pragma once

#include <optional>
#include <string>

#include "config/settings.h"

namespace lungar::config {

/// Either settings or one error line: "FILE:LINE: key 'a.b': expected ..., got ...".
struct LoadResult {
  std::optional<Settings> settings;
  std::string error;
  explicit operator bool() const { return settings.has_value(); }
};

/// Reads `path` and overlays it on the defaults. Unknown keys, wrong types, out-of-range values and
/// syntax errors are errors; nothing is clamped.
LoadResult load_settings(const std::string& path);

/// The same from TOML text; `name` stands for the file in messages.
LoadResult load_settings_from_string(const std::string& toml_text, const std::string& name);

/// A one-paragraph human summary of the settings, for start-up logs.
std::string summarize(const Settings& s);

}  // namespace lungar::config
