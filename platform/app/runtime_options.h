/// @file runtime_options.h
/// @brief The `lungar` command line's run options, and how they override the loaded settings.
/// @ingroup platform
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/App.hpp>

#include "config/base/result.h"
#include "platform/app/settings.h"

namespace lungar::platform {

struct RuntimeOptions {
  std::vector<std::string> config_paths;  ///< --config, repeatable: later files' keys over earlier ones'
  std::string asset_path;
  bool procedural = false;    ///< draw the procedural pair, not the demo's CT lungs
  std::string scenario_path;  ///< breathing/orientation scenario TOML
  std::vector<std::string> pathologies;  ///< --pathology, repeatable: replaces sim.pathology when given
  std::vector<std::string> lesions;      ///< --lesion, repeatable: replaces sim.lesion when given
  /// --breath: a source to follow instead of the model (a recording, marker:ROLE, amm, openice); given several
  /// times, recordings of one session, of which the clearest breathing is followed
  std::vector<std::string> breath_paths;
  std::string tracker;        ///< "mock" | "hid" | "igtl[:HOST[:PORT]]" | "replay:FILE"; empty: from the config
  bool headless = false;
  bool fullscreen = false;        ///< display.output = "fullscreen" (the user unit's way to cover the HMD output)
  std::string output;             ///< a name of kOutputNames; empty: from the config
  std::optional<long> frames;     ///< stop after this many frames
  std::optional<double> seconds;  ///< stop after this much time
  std::string view;               ///< a name of kViewNames; empty: from the config
  std::string mode;               ///< a name of render::kDrawModeNames
  std::string deform;             ///< a name of kDeformNames
  std::string snapshot_path;      ///< PNG of the last frame
  std::string stats_json_path;
  std::string record_path;         ///< raw tracker reports into a .trk
  std::string session_record_path;  ///< --session-record: the session's record (platform/app/session_recording.h)
  std::string sync;                ///< a name of classroom::kSyncRoleNames; empty: from the config
  std::string classroom;           ///< the classroom's name; empty: from the config
  std::optional<int> sync_domain;  ///< the DDS domain id
  std::string station;             ///< this station's name in the classroom
  std::string sync_security;       ///< this station's folder of `lungar classroom-keys`: a secure classroom
  double sync_clock_skew_ms = 0;   ///< tests: pretend this station's clock is off by this much
  std::string console;             ///< --console [ADDR:]PORT: the instructor serves its console there
  std::string console_keys;        ///< --console-keys DIR: the console's folder of `lungar classroom-keys`
  std::optional<double> stats_every_s;  ///< --stats-every: the stats JSON written again this often while running
  bool record_requested = false;   ///< --record given, with or without a file
  bool replay_truncated = false;   ///< --replay-truncated: replay a truncated .trk as far as it goes
};

/// Adds the run options to `app`; names of enumerations are checked against config's tables.
void add_runtime_options(CLI::App& app, RuntimeOptions& o);

/// Applies the command-line overrides to `s`; an error names the option ("--tracker: expected ..., got ...").
Status apply_overrides(const RuntimeOptions& o, Settings& s);

/// Outputs given no path go under `state_dir` ($XDG_STATE_HOME/lungar): snapshot.png, stats.json, and
/// recordings/<UTC time>.trk for a bare --record (whose folder this makes).
void default_output_paths(RuntimeOptions& o, const std::string& state_dir);

}  // namespace lungar::platform
