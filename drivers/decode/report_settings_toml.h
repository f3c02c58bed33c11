/// @file report_settings_toml.h
/// @brief The decoder's tables as TOML ([trackers.report], the sensors' tables, the world frame's keys and their checks
/// across keys), read and written from one field list (config/toml_visit.h); tracker_config_toml.h visits them
/// inside [trackers].
/// @ingroup drivers
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>

#include "config/toml_visit.h"
#include "drivers/decode/report_settings.h"

namespace lungar::drivers {

namespace report_toml {
inline std::size_t field_bytes(FieldType t) {
  if (t == FieldType::None) return 0;
  return (t == FieldType::I16 || t == FieldType::Fixed16) ? 2 : 4;
}

template <class Io>
void frac_bits(Io& s, std::string_view key, int& out, FieldType type) {
  s.integer(key, out, 0, 31, "bits");
  if constexpr (config::kReads<Io>) {
    const int max = type == FieldType::Fixed16 ? 15 : type == FieldType::Fixed32 ? 31 : 0;
    if (out > max) {
      s.fail(key, "expected at most " + std::to_string(max) + " fractional bits for a " + to_string(type) +
                      " field, got " + std::to_string(out));
    }
  }
}

/// A scale: any number but 0.
template <class Io>
void scale(Io& s, std::string_view key, double& out, std::string_view unit) {
  s.number(key, out, -1e6, 1e6, unit);
  if constexpr (config::kReads<Io>) {
    if (out == 0.0) s.fail(key, "expected a non-zero scale, got 0");
  }
}

/// A signed permutation of `letters` (parse_signed_axes()).
template <class Io>
void axes(Io& s, std::string_view key, std::string& out, std::string_view letters, std::string_view example) {
  s.text(key, out);
  if constexpr (config::kReads<Io>) {
    if (!parse_signed_axes(out, letters)) {
      s.fail(key, "expected each of " + std::string(letters) +
                      " once, comma-separated, each optionally negated (e.g. \"" + std::string(example) +
                      "\"), got \"" + out + "\"");
    }
  }
}

/// Each component of workspace_max_mm above workspace_min_mm's.
inline void check_workspace(config::TomlSection& s, const LayoutConfig& t) {
  for (int k = 0; k < 3; ++k) {
    if (!(t.workspace_min_mm[k] < t.workspace_max_mm[k])) {
      s.fail("workspace_max_mm", "expected every component above workspace_min_mm's, got " +
                                     std::to_string(t.workspace_max_mm[k]) +
                                     " <= " + std::to_string(t.workspace_min_mm[k]) + " at index " + std::to_string(k));
    }
  }
}

/// The report's own checks: the Euler sequence, and the station byte and the time inside the report.
inline void check_report(config::TomlSection& s, const ReportConfig& r) {
  if (r.euler_sequence.size() != 3 ||
      !parse_signed_axes(std::string{r.euler_sequence[0], ',', r.euler_sequence[1], ',', r.euler_sequence[2]}, "xyz")) {
    s.fail("euler_sequence",
           "expected three distinct axes among x, y, z (e.g. \"zyx\"), got \"" + r.euler_sequence + "\"");
  }
  const int first = r.report_id >= 0 ? 1 : 0;  // byte 0 is the report id when reports are numbered
  auto inside = [&](std::string_view key, int offset, std::size_t bytes) {
    if (offset < first || offset + static_cast<int>(bytes) > r.length) {
      s.fail(key, "expected " + std::to_string(bytes) + " byte(s) at offset " + std::to_string(offset) +
                      " to lie within the report (bytes " + std::to_string(first) + " to " +
                      std::to_string(r.length - 1) + ")");
    }
  };
  if (r.station_offset >= 0) inside("station_offset", r.station_offset, 1);
  if (r.time_offset >= 0) inside("time_offset", r.time_offset, static_cast<std::size_t>(r.time_bits / 8));
}

/// An enabled role's sensor: its fields inside the report, its station byte its own. `roles` are every role in
/// order, `sensor` one of them.
inline void check_sensor(config::TomlSection& sec, const ReportConfig& r, const SensorConfig* sensor,
                         const std::pair<const char*, SensorConfig*> (&roles)[3]) {
  const int first = r.report_id >= 0 ? 1 : 0;
  const int quat_n = r.orientation == OrientationKind::Quaternion ? 4 : 3;
  // An orientation-only report (position_type "none") has no position field to place.
  const int end_pos = r.position_type == FieldType::None
                          ? sensor->offset
                          : sensor->offset + r.position_offset + 3 * static_cast<int>(field_bytes(r.position_type));
  const int end_rot =
      sensor->offset + r.orientation_offset + quat_n * static_cast<int>(field_bytes(r.orientation_type));
  if (sensor->offset < first || std::max(end_pos, end_rot) > r.length) {
    sec.fail("offset", "expected the sensor's fields (bytes " + std::to_string(sensor->offset) + " to " +
                           std::to_string(std::max(end_pos, end_rot) - 1) + ") to lie within the " +
                           std::to_string(r.length) + "-byte report");
  }
  if (r.station_offset < 0) return;
  for (const auto& [other_name, other] : roles) {
    if (other == sensor) break;
    if (other->enabled && other->station == sensor->station) {
      sec.fail("station", "expected a station different from trackers." + std::string(other_name) + "'s, got " +
                              std::to_string(sensor->station) + " for both");
    }
  }
}

}  // namespace report_toml

/// [trackers.report].
template <class Io>
void visit(Io& s, ReportConfig& r) {
  s.integer("report_id", r.report_id, -1, 255, "(-1: unnumbered reports)");
  s.integer("length", r.length, 1, 1024, "bytes");
  s.choice("endian", r.endian, kEndianNames);
  s.integer("station_offset", r.station_offset, -1, 1023, "bytes (-1: no station byte)");
  s.integer("time_offset", r.time_offset, -1, 1023, "bytes (-1: no device time)");
  s.integer("time_bits", r.time_bits, 16, 32, "bits");
  if constexpr (config::kReads<Io>) {
    if (r.time_bits != 16 && r.time_bits != 32) {
      s.fail("time_bits", "expected 16 or 32, got " + std::to_string(r.time_bits));
    }
  }
  s.number("time_tick_us", r.time_tick_us, 1e-3, 1e6, "us");
  s.integer("position_offset", r.position_offset, 0, 1023, "bytes");
  s.choice("position_type", r.position_type, kFieldTypeNames);  // only a position may be "none"
  report_toml::frac_bits(s, "position_frac_bits", r.position_frac_bits, r.position_type);
  report_toml::scale(s, "position_scale", r.position_scale, "mm per unit");
  report_toml::axes(s, "position_components", r.position_components, "xyz", "x,-z,y");
  s.choice("orientation", r.orientation, kOrientationKindNames);
  s.integer("orientation_offset", r.orientation_offset, 0, 1023, "bytes");
  s.choice("orientation_type", r.orientation_type, kOrientationFieldTypeNames);
  report_toml::frac_bits(s, "orientation_frac_bits", r.orientation_frac_bits, r.orientation_type);
  report_toml::scale(s, "orientation_scale", r.orientation_scale, "per unit");
  if (r.orientation == OrientationKind::Quaternion) {
    report_toml::axes(s, "orientation_components", r.orientation_components, "wxyz", "x,y,z,w");
  } else {
    if constexpr (config::kReads<Io>) {
      // Keep the default quaternion list from tripping the Euler check when only `orientation` changed.
      if (r.orientation_components == ReportConfig{}.orientation_components) r.orientation_components = "z,y,x";
    }
    report_toml::axes(s, "orientation_components", r.orientation_components, "xyz", "z,y,x");
  }
  s.text("euler_sequence", r.euler_sequence);
  if constexpr (config::kReads<Io>) report_toml::check_report(s, r);
  s.finish();
}

/// [trackers.head], [trackers.patient], [trackers.stylus]; `pointer`: the stylus, which has a tip.
template <class Io>
void visit(Io& s, SensorConfig& d, bool pointer) {
  s.boolean("enabled", d.enabled);
  s.integer("station", d.station, 0, 255, "(station byte value)");
  s.integer("offset", d.offset, 0, 1023, "bytes");
  s.numbers("fixed_position_mm", d.fixed_position_mm, -1e5, 1e5, "mm");
  if (pointer) s.numbers("tip_offset_mm", d.tip_offset_mm, -1000.0, 1000.0, "mm");
  s.finish();
}

}  // namespace lungar::drivers
