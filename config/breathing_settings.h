/// @file breathing_settings.h
/// @brief [breathing] (and a scenario's [start]): the breathing pattern at t = 0 and the scenario that changes it,
/// with its TOML reader (breathing_settings.cpp). Scenarios are config's own files; sim/breathing runs them.
#pragma once

#include <string>

#include "config/base/breath_source_names.h"
#include "config/base/patient_names.h"
#include "config/toml_section.h"

namespace lungar::config {

struct BreathingSettings {
  std::string preset = kPresetNames.name(Preset::Normal);  ///< a name of kPresetNames (config/base/patient_names.h)
  double rate_bpm = 12.0;
  double ie_ratio = 0.5;          ///< inspiration : expiration time, 1:2 = 0.5
  double tidal_volume_ml = 500.0;
  std::string scenario;           ///< optional scenario TOML (relative to the config file)
  /// What drives the breath (config/base/breath_source_names.h): "model" (the above), a recorded trace (CSV or .vxp,
  /// relative to the config file), "marker:ROLE" (a chest marker tracked live) or a physiology source over DDS;
  /// `lungar --breath` overrides it.
  std::string source = kBreathSourceNames.name(BreathSource::Model);
  /// A Varian RPM trace's flagged samples (a negative validflag: RPM's gating verdict, the breath off its expected
  /// pattern or baseline, while the amplitude is still the patient's breathing): "follow" them (counted in
  /// breath_flagged_samples) or "skip" them, as a site that wants RPM's verdict may (the follower then holds and
  /// hands over to the model through each flagged stretch).
  std::string rpm_flagged = "follow";
};

/// Reads [breathing] over `b`; throws ConfigError naming the file, key and expectation.
void read_breathing_settings(TomlSection s, BreathingSettings& b);

}  // namespace lungar::config
