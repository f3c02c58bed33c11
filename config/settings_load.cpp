/// @file settings_load.cpp
/// @brief The schema of lungar's TOML config: which keys exist, their types, ranges and units.
#include "config/settings_load.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/toml_section.h"

namespace lungar::config {

namespace {

void read_display(TomlSection s, DisplaySettings& d) {
  s.choice("output", d.output,
           {{"auto", Output::Auto}, {"window", Output::Window}, {"fullscreen", Output::Fullscreen},
            {"headless", Output::Headless}});
  s.integer("width_px", d.width_px, 16, 16384, "pixels");
  s.integer("height_px", d.height_px, 16, 16384, "pixels");
  s.integer("x_px", d.x_px, -65536, 65536, "pixels");
  s.integer("y_px", d.y_px, -65536, 65536, "pixels");
  s.text("x11_output", d.x11_output);
  s.boolean("vsync", d.vsync);
  s.finish();
}

void read_hmd(TomlSection s, HmdSettings& h) {
  s.choice("view", h.view, {{"mono", View::Mono}, {"stereo", View::Stereo}});
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
  s.choice("mode", r.mode, {{"points", RenderMode::Points}, {"mesh", RenderMode::Mesh}});
  s.number("point_size_px", r.point_size_px, 1.0, 64.0, "pixels");
  s.boolean("overlay_rest", r.overlay_rest);
  s.choice("deform", r.deform, {{"gpu", Deform::Gpu}, {"cpu7", Deform::Cpu7}, {"cpu1", Deform::Cpu1}});
  s.choice("stereo_strategy", r.stereo_strategy,
           {{"per_eye", StereoStrategy::PerEye}, {"deform_once", StereoStrategy::DeformOnce}});
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

void read_trackers(TomlSection s, TrackerSettings& t) {
  s.choice("source", t.source,
           {{"mock", TrackerSource::Mock}, {"hid", TrackerSource::Hid}, {"replay", TrackerSource::Replay}});
  s.choice("mock_trajectory", t.mock_trajectory, {"static", "upright_to_supine", "head_orbit"});
  s.number("mock_rate_hz", t.mock_rate_hz, 1.0, 2000.0, "Hz");
  s.text("replay_file", t.replay_file);
  s.boolean("replay_realtime", t.replay_realtime);
  s.number("stale_ms", t.stale_ms, 1.0, 10000.0, "ms");
  s.number("reopen_backoff_ms", t.reopen_backoff_ms, 1.0, 60000.0, "ms");
  TomlSection hid = s.section("hid");
  hid.integer("vendor_id", t.hid.vendor_id);
  hid.integer("product_id", t.hid.product_id);
  hid.text("serial", t.hid.serial);
  hid.text("path", t.hid.path);
  hid.finish();
  if (t.source == TrackerSource::Replay && t.replay_file.empty()) {
    s.fail("replay_file", "expected a .trk file when source = \"replay\", got nothing");
  }
  s.finish();
}

void read_registration(TomlSection s, RegistrationSettings& r) {
  s.numbers("translation_mm", r.translation_mm, -1e4, 1e4, "mm");
  s.numbers("rotation_wxyz", r.rotation_wxyz, -1.0, 1.0, "");
  const auto& q = r.rotation_wxyz;
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::abs(norm - 1.0) > 1e-3) {
    s.fail("rotation_wxyz", "expected a unit quaternion (norm 1 within 1e-3), got norm " + std::to_string(norm));
  }
  s.finish();
}

void read_sim(TomlSection s, SimSettings& m) {
  s.text("asset", m.asset);
  s.choice("orientation_mode", m.orientation_mode,
           {{"exact", OrientationMode::Exact}, {"paper_interp", OrientationMode::PaperInterp}});
  s.finish();
}

LoadResult parse(const std::string& text, const std::string& name) {
  LoadResult result;
  toml::table root;
  try {
    root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    result.error = name + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                   ": TOML syntax error: " + std::string(e.description());
    return result;
  }
  Settings s;
  s.source = name;
  try {
    TomlSection top(&root, "", name);
    read_display(top.section("display"), s.display);
    read_hmd(top.section("hmd"), s.hmd);
    read_render(top.section("render"), s.render);
    read_breathing(top.section("breathing"), s.breathing);
    read_trackers(top.section("trackers"), s.trackers);
    read_registration(top.section("registration"), s.registration);
    read_sim(top.section("sim"), s.sim);
    top.finish();
  } catch (const ConfigError& e) {
    result.error = e.what();
    return result;
  }
  result.settings = std::move(s);
  return result;
}

}  // namespace

LoadResult load_settings_from_string(const std::string& toml_text, const std::string& name) {
  return parse(toml_text, name);
}

LoadResult load_settings(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    LoadResult r;
    r.error = path + ": cannot read the config: expected a TOML file, " +
              (std::filesystem::exists(path, ec) ? std::string("got something that is not a regular file")
                                                 : std::string("got no such file"));
    return r;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) {
    LoadResult r;
    r.error = path + ": cannot read the config: read error";
    return r;
  }
  LoadResult r = parse(text.str(), path);
  if (r) {
    // Relative paths inside a config are relative to the config's folder.
    const auto dir = std::filesystem::path(path).parent_path();
    auto resolve = [&](std::string& p) {
      if (!p.empty() && std::filesystem::path(p).is_relative()) p = (dir / p).lexically_normal().string();
    };
    resolve(r.settings->breathing.scenario);
    resolve(r.settings->trackers.replay_file);
    resolve(r.settings->sim.asset);
  }
  return r;
}

}  // namespace lungar::config
