/// @file settings_load.cpp
/// @brief The schema of lungar's TOML config: which keys exist, their types, ranges and units ([trackers]'s are the
/// drivers', drivers/tracker/tracker_config_toml.h).
#include "config/settings_load.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/toml_section.h"
#include "drivers/tracker/tracker_config_toml.h"  // [trackers], the drivers' own schema

namespace lungar::config {

namespace {

void read_display(TomlSection s, DisplaySettings& d) {
  s.choice("output", d.output, kOutputNames);
  s.integer("width_px", d.width_px, 16, 16384, "pixels");
  s.integer("height_px", d.height_px, 16, 16384, "pixels");
  s.integer("x_px", d.x_px, -65536, 65536, "pixels");
  s.integer("y_px", d.y_px, -65536, 65536, "pixels");
  s.text("x11_output", d.x11_output);
  s.boolean("vsync", d.vsync);
  s.number("max_fps", d.max_fps, 0.0, 1000.0, "frames/s");
  TomlSection xr = s.section("openxr");
  xr.choice("head", d.openxr.head, kXrHeadNames);
  xr.choice("reference_space", d.openxr.reference_space, kXrSpaceNames);
  xr.finish();
  s.finish();
}

void read_hmd(TomlSection s, HmdSettings& h) {
  s.choice("view", h.view, kViewNames);
  s.choice("layout", h.layout, {"side_by_side"});
  s.integer("eye_width_px", h.eye_width_px, 16, 8192, "pixels");
  s.integer("eye_height_px", h.eye_height_px, 16, 8192, "pixels");
  s.number("ipd_mm", h.ipd_mm, 40.0, 90.0, "mm");
  s.number("fov_inner_deg", h.fov_inner_deg, 1.0, 89.0, "degrees");
  s.number("fov_outer_deg", h.fov_outer_deg, 1.0, 89.0, "degrees");
  s.number("fov_up_deg", h.fov_up_deg, 1.0, 89.0, "degrees");
  s.number("fov_down_deg", h.fov_down_deg, 1.0, 89.0, "degrees");
  s.numbers("head_to_eye_mm", h.head_to_eye_mm, -500.0, 500.0, "mm");
  s.number("near_mm", h.near_mm, 1.0, 1e5, "mm");
  s.number("far_mm", h.far_mm, 1.0, 1e6, "mm");
  s.number("prediction_max_ms", h.prediction_max_ms, 0.0, 200.0, "ms");
  if (h.far_mm <= h.near_mm) {
    s.fail("far_mm", "expected far_mm greater than near_mm (" + std::to_string(h.near_mm) + " mm)");
  }
  TomlSection lens = s.section("lens");
  lens.boolean("enabled", h.lens.enabled);
  lens.numbers("k1", h.lens.k1, -1.0, 1.0, "");
  lens.numbers("k2", h.lens.k2, -1.0, 1.0, "");
  lens.finish();
  s.finish();
}

void read_render(TomlSection s, RenderSettings& r) {
  s.choice("mode", r.mode, kRenderModeNames);
  s.number("point_size_px", r.point_size_px, 1.0, 64.0, "pixels");
  s.boolean("overlay_rest", r.overlay_rest);
  s.choice("deform", r.deform, kDeformNames);
  s.choice("stereo_strategy", r.stereo_strategy, kStereoStrategyNames);
  s.boolean("lod", r.lod);
  s.boolean("half_float", r.half_float);
  s.boolean("hud", r.hud);
  s.numbers("color_left", r.color_left, 0.0, 1.0, "(linear RGB)");
  s.numbers("color_right", r.color_right, 0.0, 1.0, "(linear RGB)");
  s.numbers("background", r.background, 0.0, 1.0, "(linear RGB)");
  s.finish();
}

void read_breathing(TomlSection s, BreathingSettings& b) {
  s.choice("preset", b.preset, {"normal", "emphysema", "fibrosis"});
  s.number("rate_bpm", b.rate_bpm, 2.0, 60.0, "breaths/min");
  s.number("ie_ratio", b.ie_ratio, 0.1, 4.0, "(inspiration:expiration)");
  s.number("tidal_volume_ml", b.tidal_volume_ml, 50.0, 3000.0, "mL");
  s.text("scenario", b.scenario);
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
  s.choice("orientation_mode", m.orientation_mode, kOrientationModeNames);
  s.finish();
}

void read_sync(TomlSection s, SyncSettings& y) {
  s.choice("role", y.role, kSyncRoleNames);
  s.text("classroom", y.classroom);
  if (y.classroom.empty() || y.classroom.size() > 63 || y.classroom.find_first_of("*?[]\\") != std::string::npos) {
    s.fail("classroom", "expected a name of 1 to 63 characters without * ? [ ] \\, got \"" + y.classroom + "\"");
  }
  s.integer("domain", y.domain, 0, 232, "");
  s.text("cyclonedds_xml", y.cyclonedds_xml);
  s.text("station", y.station);
  if (y.station.size() > 63) s.fail("station", "expected at most 63 characters, got \"" + y.station + "\"");
  s.number("lost_after_ms", y.lost_after_ms, 50.0, 10000.0, "ms");
  s.finish();
}

Result<Settings> parse(const std::string& text, const std::string& name) {
  auto parsed = parse_toml(text, name);
  if (!parsed) return parsed.with_context("");
  const toml::table& root = *parsed;
  Settings s;
  s.source = name;
  try {
    TomlSection top(&root, "", name);
    read_display(top.section("display"), s.display);
    read_hmd(top.section("hmd"), s.hmd);
    read_render(top.section("render"), s.render);
    read_breathing(top.section("breathing"), s.breathing);
    TomlSection trackers = top.section("trackers");
    drivers::visit(trackers, s.trackers);
    read_registration(top.section("registration"), s.registration);
    read_sim(top.section("sim"), s.sim);
    read_sync(top.section("sync"), s.sync);
    top.finish();
  } catch (const ConfigError& e) {
    return fail(e.what());
  }
  return s;
}

}  // namespace

Result<Settings> load_settings_from_string(const std::string& toml_text, const std::string& name) {
  return parse(toml_text, name);
}

Result<Settings> load_settings(const std::string& path) {
  auto text = read_toml_file(path, "config");
  if (!text) return text.with_context("");
  auto r = parse(*text, path);
  if (r) {
    // Relative paths inside a config are relative to the config's folder.
    const auto dir = std::filesystem::path(path).parent_path();
    auto resolve = [&](std::string& p) {
      if (!p.empty() && std::filesystem::path(p).is_relative()) p = (dir / p).lexically_normal().string();
    };
    resolve(r->breathing.scenario);
    resolve(r->trackers.replay_file);
    resolve(r->sim.asset);
    resolve(r->sync.cyclonedds_xml);
  }
  return r;
}

}  // namespace lungar::config
