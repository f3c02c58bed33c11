/// @file tracker_config_toml.h
/// @brief [trackers] as TOML: its own keys, and each driver's table visited through the field list declared beside
/// that driver (hid_settings_toml.h, igtl_settings_toml.h, plus_settings_toml.h, report_settings_toml.h).
/// @ingroup drivers
///
/// The field lists follow config/toml_visit.h: one visit() per table, run to read or to write, so what is written
/// reads back equal. They are templates in headers because the settings loader (platform/app/settings_load.cpp)
/// reads [trackers] with them too.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "config/base/result.h"
#include "config/toml_visit.h"
#include "drivers/decode/report_settings_toml.h"
#include "drivers/hid/hid_settings_toml.h"
#include "drivers/igtl/igtl_settings_toml.h"
#include "drivers/plus/plus_settings_toml.h"
#include "drivers/tracker/tracker_config.h"

namespace lungar::drivers {

/// The [trackers] table of a TOML document over the defaults: a lungar config file's, or a .trk header's (what
/// tracker_config_to_toml() wrote, or an older header's subset of keys). Other top-level tables are left to
/// their owners. An error is one line, "NAME:LINE: key 'trackers.x': expected ..., got ...".
Result<TrackerConfig> tracker_config_from_toml(const std::string& text, const std::string& name);
/// The same from a file.
Result<TrackerConfig> tracker_config_from_file(const std::string& path);
/// The same from several files read as one (config/toml_layers.h: a later file's keys over an earlier one's).
Result<TrackerConfig> tracker_config_from_files(const std::vector<std::string>& paths);
/// Every key of [trackers] and its tables, as a .trk header records the tracker it was made with.
std::string tracker_config_to_toml(const TrackerConfig& t);

/// [trackers] and its tables.
template <class Io>
void visit(Io& s, TrackerConfig& t) {
  s.choice("source", t.source, kTrackerSourceNames);
  s.choice("mock_trajectory", t.mock.trajectory, {"static", "upright_to_supine", "head_orbit", "bedside"});
  s.number("mock_rate_hz", t.mock.rate_hz, 1.0, 2000.0, "Hz");
  s.number("mock_noise_mm", t.mock.noise_mm, 0.0, 100.0, "mm");
  s.number("mock_dropout", t.mock.dropout, 0.0, 1.0, "(probability)");
  s.text("replay_file", t.replay_file);
  s.boolean("replay_realtime", t.replay_realtime);
  s.boolean("replay_loop", t.replay_loop);
  s.boolean("replay_truncated", t.replay_truncated);
  s.number("stale_ms", t.stale_ms, 1.0, 10000.0, "ms");
  s.number("reopen_backoff_ms", t.reopen_backoff_ms, 1.0, 60000.0, "ms");
  s.number("quat_norm_tolerance", t.quat_norm_tolerance, 1e-6, 0.5, "");
  s.numbers("workspace_min_mm", t.workspace_min_mm, -1e5, 1e5, "mm");
  s.numbers("workspace_max_mm", t.workspace_max_mm, -1e5, 1e5, "mm");
  if constexpr (config::kReads<Io>) report_toml::check_workspace(s, t);
  report_toml::axes(s, "axis_remap", t.axis_remap, "xyz", "x,-z,y");
  s.numbers("world_offset_mm", t.world_offset_mm, -1e5, 1e5, "mm");
  Io hid = s.section("hid");
  visit(hid, t.hid);
  Io igtl = s.section("igtl");
  visit(igtl, t.igtl);
  Io plus = s.section("plus");
  visit(plus, t.plus);
  Io report = s.section("report");
  visit(report, t.report);
  const std::pair<const char*, SensorConfig*> roles[] = {
      {"head", &t.head}, {"patient", &t.patient}, {"stylus", &t.stylus}};
  for (const auto& [name, sensor] : roles) {
    Io sec = s.section(name);
    visit(sec, *sensor, sensor == &t.stylus);
    if constexpr (config::kReads<Io>) {
      if (sensor->enabled) report_toml::check_sensor(sec, t.report, sensor, roles);
    }
  }
  if constexpr (config::kReads<Io>) {
    if (!t.head.enabled && !t.patient.enabled && !t.stylus.enabled) {
      s.fail("head", "expected at least one of trackers.head, trackers.patient, trackers.stylus enabled, got none");
    }
    if (t.source == TrackerSource::Replay && t.replay_file.empty()) {
      s.fail("replay_file", "expected a .trk file when source = \"replay\", got nothing");
    }
  }
  s.finish();
}

}  // namespace lungar::drivers
