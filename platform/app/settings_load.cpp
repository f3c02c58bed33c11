/// @file settings_load.cpp
/// @brief The settings tree's tables, each read by its owner's reader; the keys only the program uses ([render],
/// [registration], [sim]) are read here.
#include "platform/app/settings_load.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "config/toml_layers.h"
#include "config/toml_section.h"
#include "drivers/breath/breath_factory/breath_factory.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "platform/app/console_run.h"
#include "sim/motion/lesion.h"
#include "sim/pathology/pathology.h"

namespace lungar::platform {

namespace {

/// `[breathing] source` names a trace file, relative to the config, unless it is the model, a live marker or a
/// DDS source (even a malformed one, which --breath's check then names).
bool names_a_file(const std::string& source) { return breath::breath_kind(source) == breath::BreathKind::Trace; }

using config::TomlSection;

void read_render(TomlSection s, RenderSettings& r) {
  s.choice("mode", r.mode, render::kDrawModeNames);
  s.number("point_size_px", r.point_size_px, 1.0, 64.0, "pixels");
  s.boolean("overlay_rest", r.overlay_rest);
  s.choice("deform", r.deform, kDeformNames);
  s.choice("stereo_strategy", r.stereo_strategy, render::kStereoStrategyNames);
  s.boolean("lod", r.lod);
  s.boolean("half_float", r.half_float);
  s.boolean("hud", r.hud);
  s.boolean("ventilation_map", r.ventilation_map);
  s.number("ventilation_full_scale_mm", r.ventilation_full_scale_mm, 1.0, 100.0, "mm");
  s.numbers("color_left", r.color_left, 0.0, 1.0, "(linear RGB)");
  s.numbers("color_right", r.color_right, 0.0, 1.0, "(linear RGB)");
  s.numbers("color_lesion", r.color_lesion, 0.0, 1.0, "(linear RGB)");
  s.numbers("background", r.background, 0.0, 1.0, "(linear RGB)");
  s.finish();
}

// A rigid pose: translation in mm, rotation a unit quaternion (w, x, y, z).
void read_pose(TomlSection& s, const char* translation_key, std::array<double, 3>& t, const char* rotation_key,
               std::array<double, 4>& q) {
  s.numbers(translation_key, t, -1e4, 1e4, "mm");
  s.numbers(rotation_key, q, -1.0, 1.0, "");
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::abs(norm - 1.0) > 1e-3) {
    s.fail(rotation_key, "expected a unit quaternion (norm 1 within 1e-3), got norm " + std::to_string(norm));
  }
}

void read_registration(TomlSection s, RegistrationSettings& r) {
  read_pose(s, "translation_mm", r.translation_mm, "rotation_wxyz", r.rotation_wxyz);
  read_pose(s, "xr_space_translation_mm", r.xr_space_translation_mm, "xr_space_rotation_wxyz",
            r.xr_space_rotation_wxyz);
  s.finish();
}

void read_sim(TomlSection s, SimSettings& m) {
  s.text("asset", m.asset);
  s.choice("orientation_mode", m.orientation_mode, sim::kForceModeNames);
  s.texts("pathology", m.pathologies);
  for (const std::string& spec : m.pathologies) {
    if (auto p = sim::parse_pathology(spec); !p) s.fail("pathology", p.error());
  }
  if (Status distinct = sim::check_pathologies(m.pathologies); !distinct) s.fail("pathology", distinct.error());
  s.texts("lesion", m.lesions);
  for (const std::string& spec : m.lesions) {
    if (auto l = sim::parse_lesion(spec, "lesion"); !l) s.fail("lesion", l.error());
  }
  s.finish();
}

void read_console(TomlSection s, ConsoleSettings& c) {
  s.text("listen", c.listen);
  if (auto listen = parse_listen(c.listen); !c.listen.empty() && !listen) s.fail("listen", listen.error());
  s.text("keys", c.keys);
  s.text("scenarios", c.scenarios);
  s.finish();
}

/// The settings a (possibly merged) tree holds over the defaults; `name` is what errors call a value with no file.
Result<Settings> read_tree(const toml::table& tree, const std::string& name) {
  Settings s;
  s.source = name;
  try {
    TomlSection top(&tree, "", name);
    read_display_settings(top.section("display"), s.display);
    read_hmd_settings(top.section("hmd"), s.hmd);
    read_render(top.section("render"), s.render);
    config::read_breathing_settings(top.section("breathing"), s.breathing);
    TomlSection trackers = top.section("trackers");
    drivers::visit(trackers, s.trackers());
    read_registration(top.section("registration"), s.registration);
    read_sim(top.section("sim"), s.sim);
    classroom::read_sync_settings(top.section("sync"), s.sync);
    read_console(top.section("console"), s.console);
    top.finish();
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  return s;
}

/// A relative path inside a config is relative to the folder of the file that set it (of several, the last).
void resolve_relative_paths(const toml::table& tree, Settings& s) {
  auto resolve = [&](std::string_view key_path, std::string& p) {
    const toml::node* node = tree.at_path(key_path).node();
    if (node == nullptr || p.empty() || !std::filesystem::path(p).is_relative()) return;
    const auto dir = std::filesystem::path(config::source_file(*node, "")).parent_path();
    p = (dir / p).lexically_normal().string();
  };
  resolve("breathing.scenario", s.breathing.scenario);
  if (names_a_file(s.breathing.source)) resolve("breathing.source", s.breathing.source);
  resolve("trackers.replay_file", s.trackers().replay_file);
  resolve("sim.asset", s.sim.asset);
  resolve("sync.cyclonedds_xml", s.sync.cyclonedds_xml);
  resolve("sync.security", s.sync.security);
  resolve("console.keys", s.console.keys);
  resolve("console.scenarios", s.console.scenarios);
}

}  // namespace

Result<Settings> load_settings_from_string(const std::string& toml_text, const std::string& name) {
  auto parsed = config::parse_toml(toml_text, name);
  if (!parsed) return parsed.with_context("");
  return read_tree(*parsed, name);
}

Result<Settings> load_settings(const std::vector<std::string>& paths) {
  auto tree = config::parse_toml_files(paths, "config");
  if (!tree) return tree.with_context("");
  auto r = read_tree(*tree, config::join_paths(paths));
  if (r) resolve_relative_paths(*tree, *r);
  return r;
}

Result<Settings> load_settings(const std::string& path) { return load_settings(std::vector<std::string>{path}); }

Result<Settings> load_chosen_settings(const config::ConfigChoice& choice) {
  if (choice.paths.empty()) return Settings{};
  return load_settings(choice.paths);
}

std::string summarize(const Settings& s, const config::Scenario* scenario) {
  const config::BreathingSettings& b = scenario ? scenario->start : s.breathing;
  std::ostringstream o;
  o << "config " << s.source << ": output " << to_string(s.display.output)
    << (s.display.output == Output::OpenXr ? std::string(" (head ") + to_string(s.display.openxr.head) + ")" : "")
    << ", view " << to_string(s.hmd.view) << " (" << s.hmd.eye_width_px << "x" << s.hmd.eye_height_px
    << " per eye, ";
  if (s.hmd.display_calibration) {
    o << "eyes from the display calibration)";
  } else {
    o << "IPD " << s.hmd.ipd_mm << " mm)";
  }
  o << ", " << render::to_string(s.render.mode) << " at " << s.render.point_size_px << " px, deform "
    << to_string(s.render.deform) << ", breathing " << b.preset << " " << b.rate_bpm << "/min V_T " << b.tidal_volume_ml
    << " mL"
    << (scenario ? " (the scenario " + (scenario->name.empty() ? scenario->source : scenario->name) + "'s start)"
                 : std::string())
    << ", tracker " << drivers::to_string(s.trackers().source)
    << (s.trackers().source == drivers::TrackerSource::Mock ? " (" + s.trackers().mock.trajectory + ")" : std::string())
    << ", orientation " << sim::to_string(s.sim.orientation_mode);
  return o.str();
}

}  // namespace lungar::platform
