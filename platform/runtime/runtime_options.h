/// @file runtime_options.h
/// @brief The `lungar` command line's run options, and how they override the loaded settings.
#pragma once

#include <optional>
#include <string>

#include "config/settings.h"

namespace lungar::platform {

struct RuntimeOptions {
  std::string config_path;
  std::string asset_path;
  std::string scenario_path;     ///< breathing/orientation scenario TOML
  std::string tracker;          ///< "mock" | "hid" | "replay:FILE"; empty: from the config
  bool headless = false;
  std::optional<long> frames;   ///< stop after this many frames
  std::optional<double> seconds;  ///< stop after this much time
  std::string view;             ///< "mono" | "stereo"; empty: from the config
  std::string mode;             ///< "points" | "mesh"
  std::string deform;           ///< "gpu" | "cpu7" | "cpu1"
  std::string snapshot_path;    ///< PNG of the last frame
  std::string stats_json_path;
  std::string record_path;      ///< raw tracker reports into a .trk
};

/// Applies the command-line overrides to `s`. Returns an error line ("--tracker: expected ..., got ...") or "".
std::string apply_overrides(const RuntimeOptions& o, config::Settings& s);

}  // namespace lungar::platform
