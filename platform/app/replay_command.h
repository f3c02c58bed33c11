/// @file replay_command.h
/// @brief `lungar replay SESSION`: a session record (platform/record/) played back through the real Runtime on any
///        output `lungar` has: the recorded breath, patient and pathologies, the lungs rebuilt from its header.
/// @ingroup platform
#pragma once

#include <string>

#include <CLI/App.hpp>

#include "platform/app/runtime_options.h"
#include "platform/app/settings.h"

namespace lungar::platform {

struct ReplayOptions {
  std::string session;          ///< the record
  std::string pace = "real";    ///< real: in real time at the output's pace; frames: each recorded frame once
  double snapshot_every_s = 0;  ///< a snapshot this often (session time); 0: none but the last
  std::string snapshot_dir;     ///< where the series goes (replay-SSSSS.SSS.png)
  std::string trace_csv;        ///< one row per replayed frame
  std::string timeline_csv;     ///< the debrief sheet
  std::string console;          ///< [ADDR:]PORT: the console page served read-only while it plays; empty: none
  std::string console_keys;  ///< the console's folder (DIR/console); empty: [console] keys, else beside sync.security
};

/// Adds the `replay` subcommand (lungar's own options, --output, --snapshot, --stats-json, --config, fall through
/// to it).
CLI::App* add_replay_command(CLI::App& app, ReplayOptions& r);

/// Plays the record back with `s` (the viewer's display and drawing; the record's lungs, registration and
/// pathologies) and `o` (--output, --snapshot, --stats-json, --asset for a record whose asset moved). The exit code:
/// 2 for a bad record or option, 1 when the replay fails.
int run_replay(const ReplayOptions& r, Settings s, const RuntimeOptions& o);

}  // namespace lungar::platform
