/// @file breathe_main.cpp
/// @brief lungar-breathe: runs the breathing driver (and a scenario) without graphics and prints CSV for plots:
///        the time series (t, P, V, dV, phase, orientation), or the three pressure-volume curves, or the presets;
///        or, as one JSON object, the exhale path of steady breathing against 4-D CT.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "config/base/clock.h"
#include "config/base/command_line.h"
#include "drivers/breath/physiology/physiology_feed.h"
#include "drivers/breath/trace/clearest_trace.h"
#include "drivers/classroom/classroom_station.h"
#include "lungar/version.h"
#include "platform/app/scenario_adapter.h"
#include "platform/app/settings_load.h"
#include "sim/breathing/breath_follower.h"
#include "sim/breathing/breath_trace.h"
#include "sim/breathing/exhale_path.h"
#include "sim/breathing/orientation.h"
#include "sim/breathing/pattern.h"
#include "sim/breathing/pv_curve.h"

namespace {

using namespace lungar;

/// One error line on stderr; the exit code of a bad input.
int fail_with(const std::string& message) {
  std::fprintf(stderr, "lungar-breathe: %s\n", message.c_str());
  return 2;
}

void print_curves() {
  std::printf("p_cmh2o");
  for (sim::Preset id : sim::kAllPresets) std::printf(",v_%s_ml", std::string(sim::to_string(id)).c_str());
  std::printf("\n");
  for (int k = -20; k <= 4 * static_cast<int>(sim::kMaxTranspulmonaryCmH2O); ++k) {
    const double p = 0.25 * k;
    std::printf("%.2f", p);
    for (sim::Preset id : sim::kAllPresets) std::printf(",%.3f", sim::pv_preset(id).curve.volume_ml(p));
    std::printf("\n");
  }
}

void print_presets(double tidal_volume_ml) {
  std::printf(
      "preset,a_ml,b_ml,c_cmh2o,d_cmh2o,p_frc_cmh2o,frc_ml,tlc_ml,compliance_frc_ml_per_cmh2o,"
      "swing_cmh2o,compliance_tidal_ml_per_cmh2o\n");
  for (sim::Preset id : sim::kAllPresets) {
    const sim::PvPreset& p = sim::pv_preset(id);
    const double frc = p.frc_ml();
    const double swing = p.curve.pressure_cmh2o(frc + tidal_volume_ml) - p.p_frc_cmh2o;
    std::printf("%s,%.0f,%.0f,%.2f,%.2f,%.2f,%.1f,%.1f,%.1f,%.3f,%.1f\n", std::string(sim::to_string(p.id)).c_str(),
                p.curve.a_ml, p.curve.b_ml, p.curve.c_cmh2o, p.curve.d_cmh2o, p.p_frc_cmh2o, frc,
                p.curve.volume_ml(sim::kMaxTranspulmonaryCmH2O), p.curve.compliance_ml_per_cmh2o(p.p_frc_cmh2o), swing,
                tidal_volume_ml / swing);
  }
}

void print_series(const sim::BreathingScript& script, double seconds, double dt) {
  std::printf("t_s,p_cmh2o,p_applied_cmh2o,v_ml,v_frc_ml,dv_ml,phase,breath,qw,qx,qy,qz,tilt_deg,gx,gy,gz\n");
  const auto n = static_cast<long>(std::floor(seconds / dt + 1e-9));
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * dt;
    const sim::BreathingSample s = script.driver.at(t);
    const Eigen::Quaterniond q = script.orientation.at(t);
    const Eigen::Vector3d g = sim::gravity_in_lung_frame(q);
    std::printf("%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%s,%lld,%.6f,%.6f,%.6f,%.6f,%.3f,%.6f,%.6f,%.6f\n", t, s.p_cmh2o,
                s.p_applied_cmh2o, s.v_ml, s.v_frc_ml, s.dv_ml, sim::to_string(s.phase),
                static_cast<long long>(s.breath), q.w(), q.x(), q.y(), q.z(), sim::tilt_from_upright_deg(q), g.x(),
                g.y(), g.z());
  }
}

/// The follower's CSV: its header, and one row at `t`.
void print_follow_header() { std::printf("t_s,dv_ml,breath_state,surrogate,model_dv_ml,apnoea,irregular\n"); }
void print_follow_row(double t, const sim::FollowerOutput& o, double model) {
  std::printf("%.4f,%.3f,%s,%.6g,%.3f,%d,%d\n", t, o.dv_ml, sim::kBreathStateNames.name(o.state), o.surrogate, model,
              o.apnoea ? 1 : 0, o.irregular ? 1 : 0);
}

/// The follower's parameters for a run of `script`: V_T, and the preset's inspiratory capacity as the highest dV.
sim::FollowerParams follower_params(const sim::BreathingScript& script, double tidal_ml) {
  sim::FollowerParams fp;
  fp.tidal_volume_ml = tidal_ml;
  const sim::PvPreset& preset = sim::pv_preset(script.start.preset);
  fp.max_ml = std::min(3.0 * tidal_ml, sim::max_tidal_volume_ml(preset, preset.p_frc_cmh2o));
  return fp;
}

/// --breath FILE: the follower driven by a recorded surrogate, sampled every dt, with the model's dV for its
/// handovers; a trace's flagged samples followed or skipped ([breathing] rpm_flagged).
int print_followed(const sim::BreathingScript& script, const std::string& trace_path, double tidal_ml,
                   const std::string& rpm_flagged, std::optional<double> seconds, double dt) {
  auto trace = sim::read_breath_trace(trace_path);
  if (!trace) return fail_with(trace.error());
  const int flagged = trace->flagged;
  if (trace->skipped > 0)
    std::fprintf(stderr, "lungar-breathe: %s: %d rows whose time went back dropped (the first at line %d)\n",
                 trace_path.c_str(), trace->skipped, trace->first_skipped_line);
  const bool skip = rpm_flagged == "skip";
  if (skip) trace = sim::without_flagged(trace.take());
  sim::BreathFollower follower(follower_params(script, tidal_ml));
  const double end = seconds.value_or(trace->samples.back().t_s);
  print_follow_header();
  std::size_t next = 0;
  long states[3] = {0, 0, 0};
  const auto n = static_cast<long>(std::floor(end / dt + 1e-9));
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * dt;
    for (; next < trace->samples.size() && trace->samples[next].t_s <= t; ++next)
      follower.add(trace->samples[next].t_s, trace->samples[next].value);
    const double model = script.driver.at(t).dv_ml;
    const sim::FollowerOutput o = follower.at(t, model);
    ++states[static_cast<int>(o.state)];
    print_follow_row(t, o, model);
  }
  // The summary on stderr, so that stdout stays one CSV.
  std::fprintf(stderr,
               "lungar-breathe: %s %s: %zu samples (%d flagged by the recorder, %s), %d breaths found (the file marks "
               "%d peaks), %.1f/min at the end, %d irregular, %d apnoeas; following %.0f %% of the run; dV held by "
               "its bounds (-V_T/2, %.0f mL) at %ld of %ld steps\n",
               trace->format.c_str(), trace_path.c_str(), trace->samples.size(), flagged,
               skip ? "skipped" : "followed", follower.breaths(), trace->peaks_marked, follower.rate_per_min(),
               follower.irregular_breaths(), follower.apnoeas(),
               100.0 * static_cast<double>(states[static_cast<int>(sim::BreathState::Following)]) /
                   static_cast<double>(n + 1),
               follower.max_ml(), follower.bounded_samples(), n + 1);
  return 0;
}

/// --breath amm|openice: the follower driven live by a mannequin or a ventilator over DDS for `seconds`, a row
/// every dt as it happens (time zero: the start), then what came and what was dropped on stderr.
int print_followed_live(const sim::BreathingScript& script, const breath::physiology::PhysiologySpec& spec,
                        const std::string& cyclonedds_xml, double tidal_ml, double seconds, double dt) {
  const std::int64_t t0 = monotonic_ns();
  auto feed = breath::physiology::PhysiologyFeed::open(spec, cyclonedds_xml, t0);
  if (!feed) return fail_with(feed.error());
  sim::FollowerParams fp = follower_params(script, tidal_ml);
  fp.in_ml = (*feed)->in_ml();
  breath::Followers followers{sim::BreathFollower(fp), {sim::BreathFollower(fp), sim::BreathFollower(fp)}};
  std::fprintf(stderr, "lungar-breathe: following %s for %.1f s\n", (*feed)->describe().c_str(), seconds);
  print_follow_header();
  const auto n = static_cast<long>(std::floor(seconds / dt + 1e-9));
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * dt;
    std::this_thread::sleep_until(std::chrono::steady_clock::time_point(
        std::chrono::nanoseconds(t0 + static_cast<std::int64_t>(t * 1e9))));
    (*feed)->feed(t, followers);
    const double model = script.driver.at(t).dv_ml;
    print_follow_row(t, followers.breath.at(t, model), model);
    std::fflush(stdout);
  }
  nlohmann::json stats;
  (*feed)->add_stats(stats);
  std::fprintf(stderr, "lungar-breathe: %s; %d breaths found, %.1f/min at the end\n", stats.dump().c_str(),
               followers.breath.breaths(), followers.breath.rate_per_min());
  return 0;
}

/// --breath: a recorded trace (the clearest of several), or a live source over DDS (amm, openice).
int follow(const sim::BreathingScript& script, const std::vector<std::string>& breaths,
           const platform::Settings& settings, std::optional<double> seconds, double dt) {
  std::string breath = breaths.front();
  const double tidal_ml = settings.breathing.tidal_volume_ml;
  if (breaths.size() > 1) {
    for (const std::string& b : breaths) {
      auto live = breath::physiology::parse_physiology_spec(b);
      if (!live) return fail_with("--breath: " + live.error());
      if (*live) return fail_with("--breath: several sources are compared only as recordings, got '" + b + "'");
    }
    std::string said;
    auto best = breath::clearest_trace(breaths, said);
    if (!best) return fail_with("--breath: " + best.error());
    std::fprintf(stderr, "lungar-breathe: %s\n", said.c_str());
    return print_followed(script, *best, tidal_ml, settings.breathing.rpm_flagged, seconds, dt);
  }
  auto live = breath::physiology::parse_physiology_spec(breath);
  if (!live) return fail_with("--breath: " + live.error());
  if (!*live) return print_followed(script, breath, tidal_ml, settings.breathing.rpm_flagged, seconds, dt);
  const std::string xml =
      settings.sync.cyclonedds_xml.empty() ? classroom::default_cyclonedds_xml() : settings.sync.cyclonedds_xml;
  return print_followed_live(script, **live, xml, tidal_ml, seconds.value_or(60.0), dt);
}

/// One JSON object on stdout: the parameters, the exhale path measured on the driver and 4-D CT's, the measured
/// tidal volume, and the equation of motion's R, C, tau and muscle-pressure peak.
int print_exhale_path(const sim::BreathingParams& params) {
  auto measured = sim::measure_exhale_path(params);
  if (!measured) return fail_with(measured.error());
  sim::Pattern pattern;
  pattern.params = params;
  if (Status e = sim::solve(pattern); !e) return fail_with(e.error());
  auto list = [](const std::array<double, 4>& a, const char* format) {
    std::string out = "[";
    char buf[32];
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::snprintf(buf, sizeof buf, format, a[i]);
      out += (i ? "," : "") + std::string(buf);
    }
    return out + "]";
  };
  const bool spontaneous = params.mode == sim::Mode::Spontaneous;
  std::printf(
      "{\"rate_bpm\":%g,\"ie_ratio\":%g,\"tidal_volume_ml\":%g,\"preset\":\"%s\",\"mode\":\"%s\","
      "\"exhale_path\":%s,\"exhale_path_4dct\":%s,\"tidal_volume_ml_measured\":%.3f",
      params.rate_bpm, params.ie_ratio, params.tidal_volume_ml, std::string(sim::to_string(params.preset)).c_str(),
      spontaneous ? "spontaneous" : "ventilator", list(measured->path, "%.4f").c_str(),
      list(sim::kExhalePath4dct, "%.2f").c_str(), measured->tidal_volume_ml);
  if (spontaneous) {
    std::printf(
        ",\"resistance_cmh2o_s_per_l\":%.3f,\"compliance_ml_per_cmh2o\":%.2f,\"tau_s\":%.4f,"
        "\"pmus_peak_cmh2o\":%.3f",
        pattern.resistance_cmh2o_s_per_l, pattern.compliance_ml_per_cmh2o, pattern.cycle.tau_s,
        pattern.pmus_peak_cmh2o);
  }
  std::printf("}\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "lungar-breathe: runs the breathing driver without graphics and prints CSV on stdout.\n"
      "By default the time series t_s, p_cmh2o, p_applied_cmh2o, v_ml, v_frc_ml, dv_ml, phase, breath, the patient\n"
      "orientation (qw..qz: lung frame in the world; tilt_deg: 0 upright, 90 lying) and gravity in the lung frame\n"
      "(gx, gy, gz). --curves prints the three pressure-volume curves; --presets their figures.\n"
      "--exhale-path prints one JSON object: the exhale path of steady breathing with the starting parameters (the\n"
      "share of the end-inhale -> half-a-breath-later volume path covered at 10, 20, 30, 40 % of the breath) beside\n"
      "4-D CT's, the measured tidal volume and the equation of motion's R, C, tau and muscle-pressure peak."};
  app.set_version_flag("--version", std::string("lungar-breathe ") + LUNGAR_VERSION);
  std::vector<std::string> config_paths;
  std::string scenario_path;
  std::optional<std::string> preset;
  std::optional<double> rate, tidal, ie, seconds;
  double dt = 0.01;
  bool curves = false, presets = false, exhale_path = false;
  app.add_option("--config", config_paths,
                 "settings TOML, repeatable (later over earlier): its [breathing] (and its scenario, if set)")
      ->allow_extra_args(false);
  app.add_option("--scenario", scenario_path, "scenario TOML (config/scenarios/*.toml); overrides the config's");
  app.add_option("--preset", preset, "normal | emphysema | fibrosis (with a scenario: the default of its [start])");
  app.add_option("--rate", rate, "breaths per minute [2, 60]");
  app.add_option("--tidal", tidal, "tidal volume, mL [50, 3000]");
  app.add_option("--ie", ie, "inspiration:expiration time ratio [0.1, 4]");
  app.add_option("--seconds", seconds, "how long to run, s (default: the scenario's duration_s, else 60)")
      ->check(CLI::Range(0.0, 86400.0));
  app.add_option("--dt", dt, "time step of the series, s (default 0.01)")->check(CLI::Range(1e-4, 10.0));
  std::vector<std::string> breath;
  app.add_option("--breath", breath,
                 "FILE: follow a recorded respiratory surrogate (CSV t_s,value, or t_s,x_mm,y_mm,z_mm for a marker; "
                 "an ExtMarker Frame;Timestamp;x;y;z file; a Varian RPM .vxp, its flagged samples as --config's "
                 "[breathing] rpm_flagged says; given several times, the one whose breathing is clearest) and print t_s, dv_ml, breath_state (following | holding | model), surrogate, "
                 "model_dv_ml, apnoea, irregular (0 | 1); or amm[@DOMAIN], openice[:volume|flow|pressure][@DOMAIN]: "
                 "follow a mannequin or a ventilator over DDS live for --seconds (default 60; Cyclone's XML from "
                 "--config's [sync] cyclonedds_xml)");
  app.add_flag("--curves", curves, "print the three pressure-volume curves, V(P) from -5 to 40 cmH2O");
  app.add_flag("--presets", presets, "print each preset's parameters, FRC, TLC, compliance and pressure swing");
  app.add_flag("--exhale-path", exhale_path,
               "print the exhale path at 10/20/30/40 % of the breath (and 4-D CT's) as one JSON object");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return lungar::exit_on_parse_error(app, e, "lungar-breathe");
  }

  platform::Settings settings;
  if (!config_paths.empty()) {
    auto loaded = platform::load_settings(config_paths);
    if (!loaded) return fail_with(loaded.error());
    settings = *loaded;
  }
  config::BreathingSettings& b = settings.breathing;
  if (preset) {
    if (!sim::preset_from_name(*preset)) {
      return fail_with("--preset: expected normal | emphysema | fibrosis, got \"" + *preset + "\"");
    }
    b.preset = *preset;
  }
  if (rate) b.rate_bpm = *rate;
  if (tidal) b.tidal_volume_ml = *tidal;
  if (ie) b.ie_ratio = *ie;
  if (!scenario_path.empty()) b.scenario = scenario_path;

  if (curves) {
    print_curves();
    return 0;
  }
  if (presets) {
    print_presets(b.tidal_volume_ml);
    return 0;
  }
  auto script = platform::load_breathing_script(b, seconds.value_or(60.0));
  if (!script) return fail_with(script.error());
  if (exhale_path) return print_exhale_path(script->start);
  if (!breath.empty()) return follow(*script, breath, settings, seconds, dt);
  print_series(*script, seconds.value_or(script->duration_s), dt);
  return 0;
}
