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
  lungar::platform::add_runtime_options(app, o);

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

  lungar::config::Settings settings;
  if (!o.config_path.empty()) {
    auto loaded = lungar::config::load_settings(o.config_path);
    if (!loaded) {
      std::fprintf(stderr, "lungar: %s\n", loaded.error().c_str());
      return 2;
    }
    settings = *loaded;
  }
  if (const lungar::Status applied = lungar::platform::apply_overrides(o, settings); !applied) {
    std::fprintf(stderr, "lungar: %s\n", applied.error().c_str());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  return lungar::platform::run_runtime(settings, o);
}
