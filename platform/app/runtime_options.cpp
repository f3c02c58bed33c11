/// @file runtime_options.cpp
/// @brief Command-line options and their overrides on top of the config file.
#include "platform/app/runtime_options.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include <CLI/CLI.hpp>

#include "config/base/clock.h"
#include "drivers/tracker/tracker_config.h"
#include "platform/app/console_run.h"
#include "sim/motion/lesion.h"
#include "sim/pathology/pathology.h"

namespace lungar::platform {

namespace {

template <class E, std::size_t N>
std::vector<std::string> names_of(const EnumNames<E, N>& table) {
  std::vector<std::string> names;
  for (const auto& [value, name] : table.entries) names.emplace_back(name);
  return names;
}

/// `text` (when given) as a value of `table`, into `out`.
template <class E, std::size_t N>
Status override_choice(const char* option, const std::string& text, const EnumNames<E, N>& table, E& out) {
  if (text.empty()) return ok();
  const auto value = table.parse(text);
  if (!value) return fail(std::string(option) + ": expected " + table.expected() + ", got '" + text + "'");
  out = *value;
  return ok();
}

/// --view: a view (mono, stereo), "ventilation" (the map over the config's view), or both, comma-separated.
Status override_view(const std::string& text, Settings& s) {
  if (text.empty()) return ok();
  bool has_view = false;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    start = end + 1;
    if (item == "ventilation") {
      s.render.ventilation_map = true;
    } else if (const auto view = kViewNames.parse(item); view && !has_view) {
      s.hmd.view = *view;
      has_view = true;
    } else {
      return fail("--view: expected mono, stereo or ventilation, or a view and the map (stereo,ventilation), got '" +
                  text + "'");
    }
  }
  return ok();
}

/// "igtl:HOST" or "igtl:HOST:PORT" (the config's port stands in when it is left out).
Status override_igtl(const std::string& tracker, drivers::TrackerConfig& t) {
  t.source = drivers::TrackerSource::Igtl;
  const std::string rest = tracker.substr(5);
  const std::size_t colon = rest.rfind(':');
  const std::string host = rest.substr(0, colon);
  if (host.empty()) return fail("--tracker: expected igtl:HOST[:PORT] with a host, got '" + tracker + "'");
  t.igtl.host = host;
  if (colon == std::string::npos) return ok();
  const std::string port = rest.substr(colon + 1);
  char* end = nullptr;
  const long p = std::strtol(port.c_str(), &end, 10);
  if (port.empty() || *end != '\0' || p < 1 || p > 65535) {
    return fail("--tracker: expected a port in [1, 65535] after igtl:HOST:, got '" + port + "'");
  }
  t.igtl.port = static_cast<int>(p);
  return ok();
}

Status override_tracker(const std::string& tracker, drivers::TrackerConfig& t) {
  if (tracker.empty()) return ok();
  if (tracker.rfind("replay:", 0) == 0 && tracker.size() > 7) {
    t.source = drivers::TrackerSource::Replay;
    t.replay_file = tracker.substr(7);
    return ok();
  }
  if (tracker.rfind("igtl:", 0) == 0) return override_igtl(tracker, t);
  const auto source = drivers::kTrackerSourceNames.parse(tracker);
  if (!source || *source == drivers::TrackerSource::Replay) {
    return fail("--tracker: expected mock, hid, igtl[:HOST[:PORT]] or replay:FILE.trk, got '" + tracker + "'");
  }
  t.source = *source;
  return ok();
}

/// Declares, under `group` in --help, the options `add` adds; the options added after go where they went before.
template <typename Add>
void grouped(CLI::App& app, const char* group, const Add& add) {
  const std::string before = app.option_defaults()->get_group();
  app.option_defaults()->group(group);
  add();
  app.option_defaults()->group(before);
}

/// What is drawn and what drives it: the settings, the lungs, their breath, the scenario, the tracker.
void add_input_options(CLI::App& app, RuntimeOptions& o) {
  app.add_option("--config", o.config_paths,
                 "settings TOML, repeatable: a later file's keys over an earlier one's (a profile, then what "
                 "`calibrate` wrote) (default: $XDG_CONFIG_HOME/lungar/lungar.toml, else /etc/lungar/lungar.toml, "
                 "else built-in; every key: default.toml)")
      ->allow_extra_args(false);
  auto* asset = app.add_option("--asset", o.asset_path, "baked .lungbake asset (default: the demo's CT lungs, cached)");
  app.add_flag("--procedural", o.procedural, "draw the procedural pair of lungs instead of the demo's CT lungs")
      ->excludes(asset);
  app.add_option("--pathology", o.pathologies,
                 "SPEC, repeatable, each pathology once: " + sim::pathology_syntaxes() + "; default: sim.pathology")
      ->allow_extra_args(false);
  app.add_option("--lesion", o.lesions,
                 "NAME=x,y,z,radius_mm, repeatable: a lesion (a tumour) inside a lung, in the asset's frame (LPS, "
                 "mm), drawn in its own colour through the lungs and moving with the tissue around it; its "
                 "excursion is in the stats JSON's lesions (default: sim.lesion)")
      ->allow_extra_args(false);
  app.add_option("--breath", o.breath_paths,
                 "FILE: breathe with a recorded respiratory surrogate (CSV t_s,value or t_s,x_mm,y_mm,z_mm, a Varian "
                 "RPM .vxp or an ExtMarker export), the model taking over before calibration and when the trace "
                 "ends; given several times (the markers of one session), the one whose breathing is clearest; " +
                     breath_source_prefix(BreathSource::Marker) +
                     "ROLE: with a chest marker tracked live as that role (stylus or head); " +
                     kBreathSourceNames.name(BreathSource::Amm) +
                     "[@DOMAIN]: with a mannequin's lung volumes over DDS (AMM); " +
                     kBreathSourceNames.name(BreathSource::OpenIce) +
                     "[:METRIC][@DOMAIN]: with a ventilator's waveform over DDS (OpenICE; METRIC volume, flow or "
                     "pressure)");
  app.add_option("--scenario", o.scenario_path,
                 "scenario TOML scheduling breathing changes and patient turns (see config/scenarios/)");
  app.add_option("--tracker", o.tracker,
                 "tracker source: mock | replay:FILE.trk | hid | igtl[:HOST[:PORT]] (OpenIGTLink, PlusServer or 3D "
                 "Slicer; default: from the config)");
  app.add_flag("--replay-truncated", o.replay_truncated,
               "replay a truncated .trk (a recording cut short) as far as it goes instead of refusing it");
}

/// Where the frames go, how they are drawn, for how long, and what is kept of the run.
void add_output_options(CLI::App& app, RuntimeOptions& o) {
  app.add_flag("--headless", o.headless, "draw off-screen even when a display is present");
  app.add_option("--output", o.output,
                 "auto | window | fullscreen | headless | openxr (a headset through its OpenXR runtime)")
      ->check(CLI::IsMember(names_of(kOutputNames)));
  app.add_flag("--fullscreen", o.fullscreen, "full screen on display.x11_output (the HMD), as the user unit runs it");
  app.add_option("--frames", o.frames, "stop after N frames");
  app.add_option("--seconds", o.seconds,
                 "stop after S seconds (default: the scenario's length, else 10 unless --frames; 0: until stopped)");
  app.add_option("--view", o.view,
                 "mono | stereo | ventilation, or a view and the map: stereo,ventilation (default: from the config; "
                 "ventilation colours each point by its ventilation over the last breath)")
      ->check(CLI::Validator(
          [](std::string& text) {
            Settings scratch;
            const Status s = override_view(text, scratch);
            return s ? std::string() : s.error().substr(std::string("--view: ").size());
          },
          "VIEW"));
  app.add_option("--mode", o.mode, "points | mesh")->check(CLI::IsMember(names_of(render::kDrawModeNames)));
  app.add_option("--deform", o.deform,
                 "gpu (vertex shader, eq. 7) | cpu7 (CPU eq. 7) | cpu1 (CPU eq. 1) | none (the rest shape)")
      ->check(CLI::IsMember(names_of(kDeformNames)));
  app.add_option("--snapshot", o.snapshot_path, "PNG of the last frame (default $XDG_STATE_HOME/lungar/snapshot.png)");
  app.add_option("--stats-json", o.stats_json_path, "stats JSON (default $XDG_STATE_HOME/lungar/stats.json)");
  app.add_option("--stats-every", o.stats_every_s,
                 "also write the stats JSON every SECONDS while running (a monitor, or a test, watching a station)");
  app.add_option("--record", o.record_path,
                 "record the raw tracker reports into FILE.trk, or the poses as a PLUS sequence FILE.igs.mha (3D "
                 "Slicer opens it) (no FILE: a .trk in $XDG_STATE_HOME/lungar/recordings/)")
      ->expected(0, 1);
  app.add_option("--session-record", o.session_record_path,
                 "record the session (each frame's breath and poses, the pathologies, the class's events) into FILE, "
                 "or into DIR/<UTC time>-<station>.lungarsession, crash-safe; `lungar replay FILE` plays it back");
}

void add_classroom_options(CLI::App& app, RuntimeOptions& o) {
  app.add_option("--sync", o.sync, "classroom role: off | instructor | trainee (default: the config's sync.role)")
      ->check(CLI::IsMember(names_of(classroom::kSyncRoleNames)));
  app.add_option("--classroom", o.classroom, "the classroom's name, a DDS partition (default: sync.classroom)");
  app.add_option("--sync-domain", o.sync_domain, "the DDS domain id [0, 232] (default: sync.domain)");
  app.add_option("--station", o.station,
                 "this station's name in the classroom (default: its --sync-security folder's name, else host/pid)");
  app.add_option("--sync-security", o.sync_security,
                 "join a secure classroom (DDS Security) with this station's folder from `lungar classroom-keys` "
                 "(default: sync.security; none: the classroom is open)");
  app.add_option("--console", o.console,
                 "[ADDR:]PORT: the instructor serves its console there, a web page over HTTPS that runs the class "
                 "live (default: console.listen; none: no console)");
  app.add_option("--console-keys", o.console_keys,
                 "the console's folder from `lungar classroom-keys` (DIR/console: its certificate and logins; "
                 "default: console.keys, else the folder console beside --sync-security's)");
  // For the tests alone: in no group, so --help leaves it out.
  app.add_option("--sync-clock-skew-ms", o.sync_clock_skew_ms, "pretend this station's clock is off by MS")->group("");
}

}  // namespace

void add_runtime_options(CLI::App& app, RuntimeOptions& o) {
  grouped(app, "Input", [&] { add_input_options(app, o); });
  grouped(app, "Output", [&] { add_output_options(app, o); });
  grouped(app, "Classroom", [&] { add_classroom_options(app, o); });
}

Status apply_overrides(const RuntimeOptions& o, Settings& s) {
  if (!o.asset_path.empty()) s.sim.asset = o.asset_path;
  if (!o.pathologies.empty()) {
    for (const std::string& spec : o.pathologies) {
      if (auto p = sim::parse_pathology(spec); !p) return p.with_context("--pathology: ");
    }
    if (Status distinct = sim::check_pathologies(o.pathologies); !distinct) return distinct.with_context("--pathology: ");
    s.sim.pathologies = o.pathologies;
  }
  if (!o.lesions.empty()) {
    for (const std::string& spec : o.lesions) {
      if (auto l = sim::parse_lesion(spec); !l) return fail(l.error());
    }
    s.sim.lesions = o.lesions;
  }
  if (!o.scenario_path.empty()) s.breathing.scenario = o.scenario_path;
  if (Status out = override_choice("--output", o.output, kOutputNames, s.display.output); !out) return out;
  if (o.fullscreen) s.display.output = Output::Fullscreen;
  if (o.headless) s.display.output = Output::Headless;
  if (Status t = override_tracker(o.tracker, s.trackers()); !t) return t;
  if (o.replay_truncated) s.trackers().replay_truncated = true;
  if (Status v = override_view(o.view, s); !v) return v;
  if (Status m = override_choice("--mode", o.mode, render::kDrawModeNames, s.render.mode); !m) return m;
  if (Status d = override_choice("--deform", o.deform, kDeformNames, s.render.deform); !d) return d;
  if (o.frames && *o.frames <= 0) {
    return fail("--frames: expected a positive number of frames, got " + std::to_string(*o.frames));
  }
  if (o.seconds && !(*o.seconds >= 0)) {
    return fail("--seconds: expected a duration >= 0 (0: until stopped), got " + std::to_string(*o.seconds));
  }
  if (Status r = override_choice("--sync", o.sync, classroom::kSyncRoleNames, s.sync.role); !r) return r;
  if (!o.classroom.empty()) s.sync.classroom = o.classroom;
  if (o.sync_domain) {
    if (*o.sync_domain < 0 || *o.sync_domain > 232) {
      return fail("--sync-domain: expected a DDS domain id in [0, 232], got " + std::to_string(*o.sync_domain));
    }
    s.sync.domain = *o.sync_domain;
  }
  if (!o.station.empty()) s.sync.station = o.station;
  if (!o.sync_security.empty()) s.sync.security = o.sync_security;
  if (!o.console.empty()) {
    if (auto listen = parse_listen(o.console); !listen) return listen.with_context("--console: ");
    s.console.listen = o.console;
  }
  if (!o.console_keys.empty()) s.console.keys = o.console_keys;
  if (o.stats_every_s && !(*o.stats_every_s > 0 && *o.stats_every_s <= 3600))
    return fail("--stats-every: expected a period in seconds, above 0 and at most 3600, got " +
                std::to_string(*o.stats_every_s));
  return ok();
}

void default_output_paths(RuntimeOptions& o, const std::string& state_dir) {
  if (o.snapshot_path.empty()) o.snapshot_path = state_dir + "/snapshot.png";
  if (o.stats_json_path.empty()) o.stats_json_path = state_dir + "/stats.json";
  if (o.record_requested && o.record_path.empty()) {
    std::string stamp = utc_timestamp();
    std::replace(stamp.begin(), stamp.end(), ':', '-');  // no colons: they trouble scp and other tools
    std::error_code ec;
    std::filesystem::create_directories(state_dir + "/recordings", ec);  // the .trk writer makes no folders
    o.record_path = state_dir + "/recordings/" + stamp + ".trk";
  }
}

}  // namespace lungar::platform
