/// @file lungar_main.cpp
/// @brief The `lungar` entry point: the runtime (no arguments: the demo) and `lungar calibrate`.
#include <csignal>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "config/settings_load.h"
#include "lungar/version.h"
#include "platform/registration/calibrate_command.h"
#include "platform/runtime/run.h"

namespace {

void on_signal(int) { lungar::platform::g_stop_requested.store(true); }

}  // namespace

int main(int argc, char** argv) {
  using lungar::platform::RuntimeOptions;
  CLI::App app{
      "lungar: breathing 3-D lungs superimposed on a patient simulator, for a head-mounted display.\n"
      "With no arguments it runs the demo: the procedural lungs, the mock tracker turning the patient from upright "
      "to supine, normal breathing, for 10 s; in a window when DISPLAY is set, headless otherwise; then a snapshot "
      "(out/snapshot.png), stats (out/stats.json) and a summary."};
  app.set_version_flag("--version", std::string("lungar ") + LUNGAR_VERSION);
  RuntimeOptions o;
  app.add_option("--config", o.config_path, "settings TOML (default: built-in defaults; see config/default.toml)");
  app.add_option("--asset", o.asset_path, "baked .lungbake asset (default: the cached procedural pair)");
  app.add_option("--scenario", o.scenario_path,
                 "scenario TOML scheduling breathing changes and patient turns (see config/scenarios/)");
  app.add_option("--tracker", o.tracker, "tracker source: mock | replay:FILE.trk | hid (default: from the config)");
  app.add_flag("--headless", o.headless, "draw off-screen even when a display is present");
  long frames = 0;
  double seconds = 0;
  auto* frames_opt = app.add_option("--frames", frames, "stop after N frames");
  auto* seconds_opt = app.add_option("--seconds", seconds, "stop after S seconds (default 10 unless --frames)");
  app.add_option("--view", o.view, "mono | stereo (default: from the config)");
  app.add_option("--mode", o.mode, "points | mesh");
  app.add_option("--deform", o.deform, "gpu (vertex shader, eq. 7) | cpu7 (CPU eq. 7) | cpu1 (CPU eq. 1) | none (rest shape)");
  app.add_option("--snapshot", o.snapshot_path, "PNG of the last frame (default out/snapshot.png)");
  app.add_option("--stats-json", o.stats_json_path, "stats JSON (default out/stats.json)");
  app.add_option("--record", o.record_path, "record the raw tracker reports into FILE.trk");

  lungar::platform::CalibrateOptions c;
  CLI::App* calibrate = app.add_subcommand(
      "calibrate", "register the lung model onto the patient simulator from paired fiducials (Umeyama)");
  calibrate->add_option("--model", c.model_csv, "model fiducials, CSV of x, y, z in mm (lung frame)")->required();
  calibrate->add_option("--stylus", c.stylus_csv, "touched fiducials, CSV of x, y, z in mm (patient-tracker frame)");
  calibrate->add_option("--stylus-log", c.stylus_log,
                        "tracker log (.trk) of the stylus touching each fiducial in order, held still >= 0.5 s");
  calibrate->add_option("--config", c.config_path, "settings TOML with the tracker report layout of the log");
  calibrate->add_option("--out", c.out_path, "where to write the [registration] section (TOML)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (*calibrate) return lungar::platform::run_calibrate(c);

  if (*frames_opt) o.frames = frames;
  if (*seconds_opt) o.seconds = seconds;
  lungar::config::Settings settings;
  if (!o.config_path.empty()) {
    auto loaded = lungar::config::load_settings(o.config_path);
    if (!loaded) {
      std::fprintf(stderr, "lungar: %s\n", loaded.error().c_str());
      return 2;
    }
    settings = *loaded;
  }
  if (const std::string error = lungar::platform::apply_overrides(o, settings); !error.empty()) {
    std::fprintf(stderr, "lungar: %s\n", error.c_str());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  return lungar::platform::run_runtime(settings, o);
}
