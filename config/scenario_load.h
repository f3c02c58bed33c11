/// @file scenario_load.h
/// @brief Reads a scenario TOML file, rejecting anything it does not understand with one precise message.
#pragma once

#include <optional>
#include <string>

#include "config/base/result.h"
#include "config/scenario.h"
#include "config/breathing_settings.h"

namespace lungar::config {

/// Reads `path`; an error is one line: "FILE:LINE: key 'event[2].kind': expected ..., got ...". Keys missing from [start] take their values from `defaults` (the config's [breathing]).
Result<Scenario> load_scenario(const std::string& path, const BreathingSettings& defaults = {});

/// The same from TOML text; `name` stands for the file in messages.
Result<Scenario> load_scenario_from_string(const std::string& toml_text, const std::string& name,
                                         const BreathingSettings& defaults = {});

}  // namespace lungar::config
