/// @file lungar_main.cpp
/// @brief The `lungar` entry point: the runtime (no arguments: the demo), `lungar calibrate`, `lungar doctor` and
/// `lungar replay`.
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "config/base/command_line.h"
#include "config/base/log_line.h"
#include "config/config_paths.h"
#include "drivers/classroom/classroom_keys.h"
#include "lungar/version.h"
#include "platform/app/calibrate_command.h"
#include "platform/app/calibrate_display_command.h"
#include "platform/app/replay_command.h"
#include "platform/app/run.h"
#include "platform/app/session_recording.h"
#include "platform/app/settings_load.h"
#include "platform/doctor/doctor.h"

namespace {

void on_signal(int) { lungar::platform::g_stop_requested.store(true); }

/// The subcommands beside the runtime: their options, and which one the command line chose.
struct Commands {
  CLI::App* doctor = nullptr;
  lungar::platform::CalibrateOptions calibrate;
  std::vector<double> stylus_tip;  ///< --stylus-tip-mm, three numbers when given
  CLI::App* calibrate_app = nullptr;
  lungar::platform::PivotOptions pivot;
  CLI::App* pivot_app = nullptr;
  lungar::platform::CalibrateDisplayOptions display;
  std::vector<double> display_tip, display_fiducial;  ///< calibrate-display's three numbers, when given
  CLI::App* display_app = nullptr;
  lungar::classroom::ClassroomKeysOptions keys;
  CLI::App* keys_app = nullptr;
  lungar::classroom::ClassroomRevokeOptions revoke;
  CLI::App* revoke_app = nullptr;
  lungar::platform::ReplayOptions replay;  ///< `lungar replay`: run after the settings load, as the runtime is
  CLI::App* replay_app = nullptr;
};

/// An option of three comma-separated millimetres (a point or an offset), each within a metre.
void add_point_mm(CLI::App& command, const std::string& name, std::vector<double>& into, const std::string& help) {
  command.add_option(name, into, help)->delimiter(',')->expected(3)->check(CLI::Range(-1000.0, 1000.0));
}

/// A subcommand's --config, repeatable as lungar's: each file's keys over the earlier ones'.
void add_configs(CLI::App& command, std::vector<std::string>& into, const std::string& holding) {
  command.add_option("--config", into, "settings TOML, repeatable (later over earlier), with " + holding)
      ->allow_extra_args(false);
}

/// The --config files of a command line: those before the subcommand (lungar's own), then the subcommand's.
std::vector<std::string> all_configs(const std::vector<std::string>& before, const std::vector<std::string>& own) {
  std::vector<std::string> all = before;
  all.insert(all.end(), own.begin(), own.end());
  return all;
}

/// `lungar calibrate` and `lungar calibrate pivot`.
void add_calibrate(CLI::App& app, Commands& m) {
  lungar::platform::CalibrateOptions& c = m.calibrate;
  CLI::App* calibrate = m.calibrate_app = app.add_subcommand(
      "calibrate", "register the lung model onto the patient simulator from paired fiducials (Umeyama)");
  calibrate->add_option("--model", c.model_csv, "model fiducials, CSV of x, y, z in mm (lung frame); required");
  calibrate->add_option("--stylus", c.stylus_csv, "touched fiducials, CSV of x, y, z in mm (patient-tracker frame)");
  calibrate->add_option("--stylus-log", c.stylus_log,
                        "tracker log (.trk) of the stylus touching each fiducial in order, held still >= 0.5 s");
  add_configs(*calibrate, c.config_paths,
              "the tracker report layout of the log and [trackers.stylus] tip_offset_mm (what `calibrate pivot` "
              "wrote)");
  calibrate->add_option("--out", c.out_path, "where to write the [registration] section (TOML); required");
  add_point_mm(*calibrate, "--stylus-tip-mm", m.stylus_tip,
               "x,y,z: the stylus tip in the stylus sensor's frame, mm (default: [trackers.stylus] tip_offset_mm)");
  CLI::App* pivot = m.pivot_app = calibrate->add_subcommand(
      "pivot", "find the stylus tip from a log of the stylus pivoting about it in a dimple (least squares)");
  pivot->add_option("--stylus-log", m.pivot.stylus_log, "tracker log (.trk) of the stylus pivoting")->required();
  add_configs(*pivot, m.pivot.config_paths, "the tracker report layout of the log");
  pivot->add_option("--out", m.pivot.out_path, "where to write [trackers.stylus] tip_offset_mm (TOML)")->required();
}

/// `lungar calibrate-display` and `lungar classroom-keys`.
void add_display_and_keys(CLI::App& app, Commands& m) {
  CLI::App* display = m.display_app = app.add_subcommand(
      "calibrate-display", "each eye's projection of an optical see-through HMD from SPAAM alignments (DLT)");
  display->add_option("--alignments", m.display.alignments_csv,
                      "CSV eye,x_mm,y_mm,z_mm,u_px,v_px: a tracked point in the head sensor's frame and the eye's "
                      "pixel (origin top-left) lined up with it; at least 6 per eye, 20-25 advised, 0.3-0.9 m deep. "
                      "Without it: interactive, a crosshair on the HMD for each eye in turn");
  display->add_option("--out", m.display.out_path, "where to write [hmd.display_calibration] (TOML)")->required();
  display->add_option("--report-json", m.display.report_json, "each eye's reprojection error, centre, intrinsics");
  display->add_option("--save-alignments", m.display.save_alignments,
                      "interactive: where to write the alignments gathered (default: beside --out, "
                      "NAME-alignments.csv)");
  add_configs(*display, m.display.config_paths,
              "interactive: the tracker, the display and the HMD (default: as lungar's)");
  add_point_mm(*display, "--stylus-tip-mm", m.display_tip,
               "interactive: x,y,z: the stylus tip in the stylus sensor's frame, mm (default: [trackers.stylus] "
               "tip_offset_mm)");
  add_point_mm(*display, "--fiducial-mm", m.display_fiducial,
               "interactive: x,y,z: line up with this point on the patient tracker (its sensor's frame, mm) instead "
               "of the stylus tip");
  display->add_option("--grid", m.display.grid, "interactive: N x N crosshair positions an eye (3-10)")
      ->capture_default_str();

  lungar::classroom::ClassroomKeysOptions& k = m.keys;
  CLI::App* keys = m.keys_app =
      app.add_subcommand("classroom-keys",
                         "make a secure classroom's authority, each station's identity, the signed DDS Security "
                         "governance and permissions, and the instructor's console (its HTTPS certificate and "
                         "logins) (with Debian's openssl)");
  keys->add_option("--classroom", k.classroom, "the classroom's name (its DDS partition)")->required();
  keys->add_option("--station", k.stations, "a station's name, repeatable: one folder each")
      ->required()
      ->allow_extra_args(false);
  keys->add_option("--instructor", k.instructor, "the station that teaches (default: the first --station)");
  keys->add_option("--out", k.out_dir, "a new or empty folder for the keys")->required();
  keys->add_option("--ca", k.ca_dir, "reuse the authority in this folder (ca_cert.pem, ca_key.pem)");
  keys->add_option("--days", k.days, "validity of the certificates and permissions, days")->capture_default_str();
  keys->add_option("--console-host", k.console_hosts,
                   "an IP address or DNS name the console's HTTPS certificate also names (besides localhost and "
                   "127.0.0.1): how tablets reach the instructor station; repeatable")
      ->allow_extra_args(false);
  CLI::App* revoke = m.revoke_app = app.add_subcommand(
      "classroom-revoke", "withdraw stations' identities (a lost HMD PC): the authority's revocation list, crl.pem");
  revoke->add_option("--ca", m.revoke.ca_dir, "the authority's folder (DIR/ca of classroom-keys)")->required();
  revoke->add_option("--cert", m.revoke.certs, "a station's identity_cert.pem, repeatable")->required();
}

/// The chosen subcommand's exit code; none when the command line runs the runtime.
std::optional<int> run_command(Commands& m, const lungar::platform::RuntimeOptions& o) {
  if (*m.pivot_app) {
    m.pivot.config_paths = all_configs(all_configs(o.config_paths, m.calibrate.config_paths), m.pivot.config_paths);
    return lungar::platform::run_pivot(m.pivot);
  }
  if (*m.display_app) {
    if (m.display_tip.size() == 3) m.display.stylus_tip_mm = Eigen::Vector3d(m.display_tip.data());
    if (m.display_fiducial.size() == 3) m.display.fiducial_mm = Eigen::Vector3d(m.display_fiducial.data());
    m.display.config_paths = all_configs(o.config_paths, m.display.config_paths);
    return lungar::platform::run_calibrate_display(m.display);
  }
  if (*m.keys_app) {
    auto made = lungar::classroom::make_classroom_keys(m.keys);
    if (!made) {
      std::fprintf(stderr, "lungar classroom-keys: %s\n", made.error().c_str());
      return 2;
    }
    for (const std::string& line : *made) std::printf("%s\n", line.c_str());
    return 0;
  }
  if (*m.revoke_app) {
    auto said = lungar::classroom::revoke_classroom_stations(m.revoke);
    if (!said) {
      std::fprintf(stderr, "lungar classroom-revoke: %s\n", said.error().c_str());
      return 2;
    }
    std::printf("%s\n", said->c_str());
    return 0;
  }
  if (m.stylus_tip.size() == 3) {
    m.calibrate.stylus_tip_mm = Eigen::Vector3d(m.stylus_tip[0], m.stylus_tip[1], m.stylus_tip[2]);
  }
  if (*m.calibrate_app) {
    m.calibrate.config_paths = all_configs(o.config_paths, m.calibrate.config_paths);
    return lungar::platform::run_calibrate(m.calibrate);
  }
  // The runtime's options, before `doctor` or after it (it falls through): what the run would use is checked.
  if (*m.doctor) return lungar::platform::doctor::run_doctor(o);
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  using lungar::platform::RuntimeOptions;
  CLI::App app{
      "lungar: breathing 3-D lungs superimposed on a patient simulator, for a head-mounted display.\n"
      "With no arguments it runs the demo: real lungs from CT (the shipped label map, baked once by lungar-bake and "
      "cached), the mock tracker turning the patient from upright "
      "to supine, normal breathing, for 10 s; in a window when DISPLAY is set, headless otherwise; then a snapshot "
      "and stats in $XDG_STATE_HOME/lungar/ (~/.local/state/lungar/) and a summary."};
  app.set_version_flag("--version", std::string("lungar ") + LUNGAR_VERSION);
  RuntimeOptions o;
  lungar::platform::add_runtime_options(app, o);
  Commands commands;
  commands.doctor =
      app.add_subcommand("doctor", "check this machine's set-up, one line each with the fix")->fallthrough();
  add_calibrate(app, commands);
  add_display_and_keys(app, commands);
  commands.replay_app = lungar::platform::add_replay_command(app, commands.replay);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar");
  }
  if (const std::optional<int> rc = run_command(commands, o)) return *rc;

  const auto dirs = lungar::config::XdgDirs::from_environment();
  const auto chosen = lungar::config::choose_config(o.config_paths, dirs);
  auto loaded = lungar::platform::load_chosen_settings(chosen);
  if (!loaded) {
    std::fprintf(stderr, "lungar: %s\n", loaded.error().c_str());
    return 2;
  }
  lungar::log_line("lungar", chosen.describe());
  lungar::platform::Settings settings = loaded.take();
  o.record_requested = app.get_option("--record")->count() > 0;
  lungar::platform::default_output_paths(o, lungar::config::state_dir(dirs));
  if (const lungar::Status applied = lungar::platform::apply_overrides(o, settings); !applied) {
    std::fprintf(stderr, "lungar: %s\n", applied.error().c_str());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  if (*commands.replay_app) return lungar::platform::run_replay(commands.replay, settings, o);
  // An unwritable --session-record is refused before anything slow loads.
  if (const lungar::Status writable = lungar::platform::check_session_record_path(o.session_record_path); !writable) {
    std::fprintf(stderr, "lungar: %s\n", writable.error().c_str());
    return 2;
  }
  return lungar::platform::run_runtime(settings, o);
}
