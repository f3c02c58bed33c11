/// @file settings_load.h
/// @brief Loading the whole settings tree from TOML: each table read by the reader of the library that owns it,
/// relative paths made relative to the config's folder, and one clear error naming the file, line and key.
/// @ingroup platform
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"
#include "config/config_paths.h"
#include "config/scenario.h"
#include "platform/app/settings.h"

namespace lungar::platform {

/// The defaults overlaid with `path`'s keys; relative paths inside are made relative to its folder.
Result<Settings> load_settings(const std::string& path);

/// The defaults overlaid with each file's keys in turn (a later file's key wins, tables merged key by key); a
/// relative path is relative to the folder of the file that set it; an error names that file, its line and the key.
Result<Settings> load_settings(const std::vector<std::string>& paths);

/// The defaults overlaid with TOML text; `name` is what errors call it.
Result<Settings> load_settings_from_string(const std::string& toml_text, const std::string& name);

/// The chosen files loaded over the defaults (or the defaults); the error names the file, the line and the key.
Result<Settings> load_chosen_settings(const config::ConfigChoice& choice);

/// One log line: output, view, mode, deform, breathing, tracker, orientation. With a `scenario` the breathing is its
/// start's (its [start] over [breathing]), which is what breathes, and the line says so.
std::string summarize(const Settings& s, const config::Scenario* scenario = nullptr);

}  // namespace lungar::platform
