/// @file scenario_load.h
/// @brief Reads a scenario TOML file, rejecting anything it does not understand with one precise message.
#pragma once

#include <optional>
#include <string>

#include "config/scenario.h"
#include "config/settings.h"

namespace lungar::config {

/// Either a scenario or one error line: "FILE:LINE: key 'event[2].kind': expected ..., got ...".
struct ScenarioResult {
  std::optional<Scenario> scenario;
  std::string error;
  explicit operator bool() const { return scenario.has_value(); }
};

/// Reads `path`. Keys missing from [start] take their values from `defaults` (the config's [breathing]).
ScenarioResult load_scenario(const std::string& path, const BreathingSettings& defaults = {});

/// The same from TOML text; `name` stands for the file in messages.
ScenarioResult load_scenario_from_string(const std::string& toml_text, const std::string& name,
                                         const BreathingSettings& defaults = {});

}  // namespace lungar::config
