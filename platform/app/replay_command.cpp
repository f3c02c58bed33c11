/// @file replay_command.cpp
/// @brief The record read, the scene rebuilt from its header, the Runtime made of the recorded breath, poses and
///        course, and the frames played: in real time, or each recorded frame once at its own time.
#include "platform/app/replay_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <CLI/CLI.hpp>

#include "config/base/atomic_file.h"
#include "config/base/clock.h"
#include "platform/app/console_run.h"
#include "platform/app/demo_asset.h"
#include "platform/app/log.h"
#include "platform/app/open_output.h"
#include "platform/app/run.h"
#include "platform/app/runtime_settings.h"
#include "platform/app/scene_lesions.h"
#include "platform/console/console_server.h"
#include "platform/record/recorded_breathing.h"
#include "platform/record/recorded_course.h"
#include "platform/record/recorded_poses.h"
#include "platform/record/replay_console.h"
#include "platform/record/replay_trace.h"
#include "platform/record/timeline_csv.h"
#include "platform/runtime/runtime.h"
#include "sim/force/force_sh.h"
#include "sim/pathology/pathology.h"

namespace lungar::platform {

namespace {

using record::SessionPlayback;
using record::SessionRecord;

/// Says how much of the record plays: all of it, or up to a cut (a killed station's record).
void say_what_plays(const SessionRecord& r) {
  const double last = r.frames.empty() ? 0.0 : r.frames.back().s;
  char span[96];
  std::snprintf(span, sizeof span, "%zu frames, %.2f s", r.frames.size(), last);
  if (!r.cut.empty()) {
    log_line("replay: " + r.path + ": cut at " + r.cut + " (a station stopped mid-record: killed?); replaying the " +
             span + " before it");
  } else if (!r.ended) {
    log_line("replay: " + r.path + ": no end line (the station stopped without closing it: killed?); replaying its " +
             span);
  } else {
    log_line("replay: " + r.path + ": " + span + ", recorded by " + r.header.station + " at " + r.header.started_utc);
  }
}

/// The record's lungs, registration and pathologies over the viewer's settings; one line naming the header's field
/// when one cannot be used.
Status take_the_records_scene(const SessionRecord& r, const RuntimeOptions& o, Settings& s) {
  const record::SessionHeader& h = r.header;
  if (o.asset_path.empty()) s.sim.asset = h.asset_path;
  s.sim.pathologies = h.pathologies;
  s.sim.lesions = h.lesions;
  s.registration.translation_mm = h.registration_translation_mm;
  s.registration.rotation_wxyz = h.registration_rotation_wxyz;
  const auto mode = sim::kForceModeNames.parse(h.orientation_mode);
  if (!mode)
    return fail(r.path + ":1: field 'orientation_mode': expected " + sim::kForceModeNames.expected() + ", got '" +
                h.orientation_mode + "'");
  s.sim.orientation_mode = *mode;
  s.sync.role = classroom::SyncRole::Off;  // a replay joins no classroom
  return ok();
}

/// The output, then the record's lungs on it with their course; `playback` drives the course.
Status open_replay_scene(const SessionRecord& r, Settings& s, bool procedural,
                         const std::shared_ptr<const SessionPlayback>& playback, RuntimeParts& parts) {
  auto output = open_output(s, log_line);
  if (!output) return output.with_context("");
  parts.output = output.take();
  log_line("output: " + parts.output->describe());
  DemoAssetOptions demo;
  demo.transfer_rows = s.render.deform == Deform::Cpu1;
  demo.procedural = procedural;
  demo.stop = &g_stop_requested;
  Result<DrawnAsset> drawn = load_drawn_asset(s.sim.asset, demo, log_line);
  if (!drawn) return drawn.with_context("");
  if (drawn->asset.vertex_count() != r.header.nodes) {
    return fail(r.path + ":1: field 'asset.nodes': the record drew " + std::to_string(r.header.nodes) + " nodes, " +
                (s.sim.asset.empty() ? std::string("the demo's lungs here") : s.sim.asset) + " has " +
                std::to_string(drawn->asset.vertex_count()) + ": give the recorded asset with --asset");
  }
  const sim::BakedAsset healthy = drawn->asset;
  sim::PatientState patient = sim::PatientState::of(drawn->asset);
  if (Status p = sim::apply_pathologies(drawn->asset, patient, s.sim.pathologies); !p)
    return p.with_context(r.path + ":1: field 'pathologies': ");
  auto course = record::RecordedCourse::create(playback, healthy, drawn->asset);
  if (!course) return course.with_context("");
  parts.course = course.take();
  std::string name = drawn->name;
  for (const std::string& spec : s.sim.pathologies) name += " with " + spec;
  auto scene =
      LungScene::create(std::move(drawn->asset), std::move(patient), name, {.half_float = s.render.half_float});
  if (!scene) return scene.with_context("");
  parts.scene = scene.take();
  auto lesions = scene_lesions(s.sim.lesions, parts.scene->asset());
  if (!lesions) return lesions.with_context("");
  parts.lesions = lesions.take();
  return ok();
}

/// DIR/replay-SSSSS.SSS.png: a series that sorts by its names.
std::string snapshot_name(const std::string& dir, double s) {
  char name[48];
  std::snprintf(name, sizeof name, "replay-%09.3f.png", s);
  return (std::filesystem::path(dir) / name).string();
}

/// Plays the frames; `playing_ns` is the Runtime's clock when the pace is "frames". A snapshot every
/// `r.snapshot_every_s` of session time (the frame that reaches it is drawn as the snapshot).
Status play(Runtime& runtime, const ReplayOptions& r, SessionPlayback& playback, std::int64_t& playing_ns) {
  const SessionRecord& record = playback.record();
  // At whole multiples of the period in session time (0, 5, 10 s...), each drawn by the first frame that reaches it.
  double next_snapshot_s =
      r.snapshot_every_s > 0
          ? std::ceil((playback.first_s() - SessionPlayback::kSnapS) / r.snapshot_every_s) * r.snapshot_every_s
          : 0.0;
  const auto draw = [&](double s) -> Status {
    if (r.snapshot_every_s > 0 && s >= next_snapshot_s - SessionPlayback::kSnapS) {
      while (next_snapshot_s <= s + SessionPlayback::kSnapS) next_snapshot_s += r.snapshot_every_s;
      return runtime.final_frame(snapshot_name(r.snapshot_dir, s));
    }
    return runtime.frame();
  };
  playback.start_at(monotonic_ns());
  if (r.pace == "frames") {
    for (const record::RecordedFrame& f : record.frames) {
      if (g_stop_requested.load() || !runtime.keep_running()) break;
      playing_ns = playback.ns_at(f.s);
      if (Status drawn = draw(f.s); !drawn) return drawn;
    }
    return ok();
  }
  while (!g_stop_requested.load() && runtime.keep_running()) {
    if (Status drawn = draw(playback.session_s(monotonic_ns())); !drawn) return drawn;
  }
  return ok();
}

/// The last snapshot, the stats JSON and the trace, each whole or not at all; the exit code.
int write_replay_outputs(Runtime& runtime, const ReplayOptions& r, const RuntimeOptions& o, const SessionRecord& record,
                         const record::ReplayTrace* trace, const console::ConsoleServer* console, double wall_s,
                         bool played) {
  int exit_code = played ? 0 : 1;
  // Before the last snapshot, whose frame would add a row of its own.
  const std::string trace_text = trace ? trace->csv(record.header.lungs) : "";
  const std::size_t trace_rows = trace ? trace->rows() : 0;
  if (played) {
    if (Status shot = runtime.final_frame(o.snapshot_path); !shot) {
      log_line("error: " + shot.error());
      exit_code = 1;
    } else {
      log_line("snapshot: " + o.snapshot_path);
    }
  }
  nlohmann::ordered_json stats = runtime.stats_json(wall_s);
  stats["replay"] = {{"session", record.path},
                     {"pace", r.pace},
                     {"frames_recorded", record.frames.size()},
                     {"cut", record.cut},
                     {"ended", record.ended}};
  if (!stats.contains("pathologies")) stats["pathologies"] = record.header.pathologies;
  if (console != nullptr) {
    nlohmann::json keys;
    add_console_stats(*console, keys);
    for (const auto& [key, value] : keys.items()) stats[key] = value;
  }
  if (Status written = write_file_atomically(o.stats_json_path, stats.dump(2) + "\n"); !written) {
    log_line("error: stats: " + written.error());
    exit_code = 1;
  } else {
    log_line("stats: " + o.stats_json_path);
  }
  if (trace != nullptr) {
    if (Status written = write_file_atomically(r.trace_csv, trace_text); !written) {
      log_line("error: --trace-csv: " + written.error());
      exit_code = 1;
    } else {
      log_line("trace: " + r.trace_csv + " (" + std::to_string(trace_rows) + " frames)");
    }
  }
  log_line(runtime.summary(wall_s));
  return exit_code;
}

}  // namespace

CLI::App* add_replay_command(CLI::App& app, ReplayOptions& r) {
  CLI::App* replay = app.add_subcommand(
      "replay",
      "play a session record (lungar --session-record) back on any output: the recorded breath, patient and "
      "pathologies; lungar's own options (--output, --snapshot, --stats-json, --config) apply");
  replay->fallthrough();
  replay->add_option("SESSION", r.session, "the session record (.lungarsession)")->required();
  replay
      ->add_option("--pace", r.pace,
                   "real: in real time at the output's pace, the record interpolated between its frames; frames: "
                   "each recorded frame once, at its recorded time, as fast as the output draws")
      ->check(CLI::IsMember({"real", "frames"}))
      ->capture_default_str();
  replay->add_option("--snapshot-every", r.snapshot_every_s, "a PNG every SECONDS of the session (into --snapshot-dir)")
      ->check(CLI::Range(0.001, 86400.0));
  replay->add_option("--snapshot-dir", r.snapshot_dir, "the folder of --snapshot-every's series");
  replay->add_option("--trace-csv", r.trace_csv,
                     "one row per replayed frame: session_s, breath_s, dV, each lung's dV, the pathologies drawn");
  replay->add_option("--timeline-csv", r.timeline_csv,
                     "the debrief sheet: the events, console actions and pathology changes, with dV then");
  replay->add_option("--console", r.console,
                     "[ADDR:]PORT: serve the instructor's console page there while it plays, read-only: the record's "
                     "timeline with a cursor at the replay's time, its breath, pathologies and stations, the debrief "
                     "CSV (port 0: any free one, said in the log)");
  replay->add_option("--console-keys", r.console_keys,
                     "the console's folder from `lungar classroom-keys` (DIR/console: its certificate and logins; "
                     "default: console.keys, else the folder console beside --sync-security's)");
  return replay;
}

namespace {

/// Where --console serves the replay, with the console's folder; none without --console; an error when either is not
/// usable (said before anything loads).
struct ReplayConsoleAt {
  ListenAddress at;
  std::string keys;
};
Result<std::optional<ReplayConsoleAt>> replay_console_at(const ReplayOptions& r, Settings& s) {
  if (r.console.empty()) return std::optional<ReplayConsoleAt>();
  auto listen = parse_listen(r.console);
  if (!listen) return listen.with_context("--console: ");
  if (!r.console_keys.empty()) s.console.keys = r.console_keys;
  auto keys = console_keys_dir(s);
  if (!keys) return keys.with_context("--console: ");
  return std::optional<ReplayConsoleAt>(ReplayConsoleAt{*listen, keys.take()});
}

/// The record read whole (up to a kill's tear), said in the log, and its debrief sheet written when asked for; the
/// exit code's error when it cannot play.
Result<std::shared_ptr<const SessionRecord>> read_for_replay(const ReplayOptions& r, int& exit_code) {
  auto read = record::read_session_record(r.session);
  if (!read) {
    exit_code = 2;
    return Error{read.error()};
  }
  auto record = std::make_shared<const SessionRecord>(read.take());
  say_what_plays(*record);
  exit_code = 1;
  if (!r.timeline_csv.empty()) {
    if (Status written = write_file_atomically(r.timeline_csv, record::timeline_csv(*record)); !written)
      return written.with_context("--timeline-csv: ");
    log_line("timeline: " + r.timeline_csv);
  }
  if (record->frames.empty()) return fail(r.session + ": no frame was recorded: nothing to play");
  return record;
}

/// What follows the replayed frames besides the output: the --trace-csv rows, and the console's view.
struct ReplayListeners {
  std::shared_ptr<record::ReplayTrace> trace;
  std::shared_ptr<record::ReplayConsole> view;
};
ReplayListeners add_replay_listeners(const ReplayOptions& r, const SessionRecord& record,
                                     const std::shared_ptr<SessionPlayback>& playback, bool console,
                                     RuntimeParts& parts) {
  ReplayListeners l;
  if (!r.trace_csv.empty()) {
    const double span_s = playback->last_s() - playback->first_s();
    const std::size_t rows =
        r.pace == "frames" ? record.frames.size() + 16 : static_cast<std::size_t>(span_s * 250.0) + 1024;
    l.trace = std::make_shared<record::ReplayTrace>(playback, parts.course, rows);
    parts.listeners.push_back(l.trace);
  }
  if (console) {
    l.view = std::make_shared<record::ReplayConsole>(playback);
    parts.listeners.push_back(l.view);
  }
  return l;
}

}  // namespace

int run_replay(const ReplayOptions& r, Settings s, const RuntimeOptions& o) {
  if (r.snapshot_every_s > 0 && r.snapshot_dir.empty()) {
    log_line("error: replay: --snapshot-every needs --snapshot-dir");
    return 2;
  }
  auto console_at = replay_console_at(r, s);
  if (!console_at) {
    log_line("error: replay: " + console_at.error());
    return 2;
  }
  int exit_code = 0;
  auto read = read_for_replay(r, exit_code);
  if (!read) {
    log_line("error: replay: " + read.error());
    return exit_code;
  }
  const std::shared_ptr<const SessionRecord> record = read.take();
  if (Status taken = take_the_records_scene(*record, o, s); !taken) {
    log_line("error: replay: " + taken.error());
    return 2;
  }
  // Frame by frame, the runtime's clock is the record's: a pacer (display.max_fps) on it would only slow the replay.
  if (r.pace == "frames") s.display.max_fps = 0;
  auto playback = std::make_shared<SessionPlayback>(record, monotonic_ns());
  RuntimeParts parts;
  if (Status opened = open_replay_scene(*record, s, record->header.procedural, playback, parts); !opened) {
    log_line("error: replay: " + opened.error());
    return 1;
  }
  parts.breathing = std::make_unique<record::RecordedBreathing>(playback);
  parts.poses = std::make_unique<record::RecordedPoses>(playback);
  const ReplayListeners listeners = add_replay_listeners(r, *record, playback, console_at->has_value(), parts);
  std::int64_t playing_ns = playback->ns_at(playback->first_s());
  if (r.pace == "frames") parts.clock = [&playing_ns] { return playing_ns; };
  log_line("tracker: " + parts.poses->describe());
  auto runtime = Runtime::create(runtime_config(s), std::move(parts));
  if (!runtime) {
    log_line("error: replay: " + runtime.error());
    return 1;
  }
  // Served while it plays; stopped after the outputs are written (their stats say its counts), before the view goes.
  std::unique_ptr<console::ConsoleServer> console;
  if (*console_at) {
    auto served = serve_console((*console_at)->at, (*console_at)->keys, *listeners.view,
                                [](const std::string& line) { log_line(line); });
    if (!served) {
      log_line("error: replay: " + served.error());
      return 1;
    }
    console = served.take();
  }
  const std::int64_t started = monotonic_ns();
  const Status played = play(**runtime, r, *playback, playing_ns);
  if (!played) log_line("error: replay: " + played.error());
  if (g_stop_requested.load()) log_line("stop requested; writing the outputs");
  exit_code = write_replay_outputs(**runtime, r, o, *record, listeners.trace.get(), console.get(),
                                   seconds_between(started, monotonic_ns()), played.ok());
  console.reset();
  return exit_code;
}

}  // namespace lungar::platform
