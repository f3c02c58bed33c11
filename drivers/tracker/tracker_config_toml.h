/// @file tracker_config_toml.h
/// @brief [trackers] and its tables as TOML, read and written from one field list.
/// @ingroup drivers
///
/// visit() names every key once, with its range and unit and the checks across keys, and runs over
/// config::TomlSection (reading over the values already there; every problem is an error naming file, line and
/// key) or over config::TomlWriter (writing every key, doubles at full precision), so what is written reads back
/// equal. The checks run only when reading. The field list is a template in this header because the settings
/// loader (platform/app/settings_load.cpp) reads [trackers] with it too.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "config/base/result.h"
#include "config/toml_section.h"
#include "config/toml_writer.h"
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

namespace tracker_toml {

template <class Io>
inline constexpr bool kReads = std::is_same_v<Io, config::TomlSection>;

inline std::size_t field_bytes(FieldType t) {
  if (t == FieldType::None) return 0;
  return (t == FieldType::I16 || t == FieldType::Fixed16) ? 2 : 4;
}

/// "0x02 0x01", "02 01" or "0x02,0x01": one to 4096 bytes, each one or two hex digits with an optional 0x.
inline std::optional<std::vector<std::uint8_t>> parse_hex_bytes(std::string_view text) {
  std::vector<std::uint8_t> out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (text[pos] == ' ' || text[pos] == ',' || text[pos] == '\t') {
      ++pos;
      continue;
    }
    if (text.substr(pos, 2) == "0x" || text.substr(pos, 2) == "0X") pos += 2;
    int digits = 0, value = 0;
    for (; pos < text.size() && std::isxdigit(static_cast<unsigned char>(text[pos])); ++pos, ++digits) {
      value = value * 16 +
              (std::isdigit(static_cast<unsigned char>(text[pos])) ? text[pos] - '0' : (text[pos] | 0x20) - 'a' + 10);
    }
    if (digits < 1 || digits > 2 || (pos < text.size() && text[pos] != ' ' && text[pos] != ',')) return std::nullopt;
    out.push_back(static_cast<std::uint8_t>(value));
  }
  if (out.empty() || out.size() > 4096) return std::nullopt;
  return out;
}

/// The reports as parse_hex_bytes() reads them: "0x02 0x01".
inline std::vector<std::string> hex_texts(const std::vector<std::vector<std::uint8_t>>& reports) {
  std::vector<std::string> out;
  for (const auto& bytes : reports) {
    std::string s;
    for (std::uint8_t b : bytes) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "%s0x%02x", s.empty() ? "" : " ", static_cast<unsigned>(b));
      s += buf;
    }
    out.push_back(std::move(s));
  }
  return out;
}

template <class Io>
void frac_bits(Io& s, std::string_view key, int& out, FieldType type) {
  s.integer(key, out, 0, 31, "bits");
  if constexpr (kReads<Io>) {
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
  if constexpr (kReads<Io>) {
    if (out == 0.0) s.fail(key, "expected a non-zero scale, got 0");
  }
}

/// A signed permutation of `letters` (parse_signed_axes()).
template <class Io>
void axes(Io& s, std::string_view key, std::string& out, std::string_view letters, std::string_view example) {
  s.text(key, out);
  if constexpr (kReads<Io>) {
    if (!parse_signed_axes(out, letters)) {
      s.fail(key, "expected each of " + std::string(letters) +
                      " once, comma-separated, each optionally negated (e.g. \"" + std::string(example) +
                      "\"), got \"" + out + "\"");
    }
  }
}

/// Each component of workspace_max_mm above workspace_min_mm's.
inline void check_workspace(config::TomlSection& s, const TrackerConfig& t) {
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

}  // namespace tracker_toml

/// [trackers.hid].
template <class Io>
void visit(Io& s, HidConfig& h) {
  s.integer("vendor_id", h.vendor_id);
  s.integer("product_id", h.product_id);
  s.text("serial", h.serial);
  s.text("path", h.path);
  s.number("read_timeout_ms", h.read_timeout_ms, 1.0, 1000.0, "ms");
  std::vector<std::string> reports = tracker_toml::hex_texts(h.init_feature_reports);
  s.texts("init_feature_reports", reports);
  if constexpr (tracker_toml::kReads<Io>) {
    std::vector<std::vector<std::uint8_t>> parsed;
    for (std::size_t k = 0; k < reports.size(); ++k) {
      auto bytes = tracker_toml::parse_hex_bytes(reports[k]);
      if (!bytes) {
        s.fail("init_feature_reports", "expected hex bytes, report id first (e.g. \"0x02 0x01\"), got \"" + reports[k] +
                                           "\" at index " + std::to_string(k));
      }
      parsed.push_back(std::move(*bytes));
    }
    h.init_feature_reports = std::move(parsed);
  }
  s.finish();
}

/// [trackers.igtl].
template <class Io>
void visit(Io& s, IgtlConfig& g) {
  s.text("host", g.host);
  if constexpr (tracker_toml::kReads<Io>) {
    if (g.host.empty()) s.fail("host", "expected a host name or address (e.g. \"127.0.0.1\"), got \"\"");
  }
  s.integer("port", g.port, 1, 65535, "(TCP port)");
  const std::pair<const char*, std::string*> names[] = {
      {"head", &g.head}, {"patient", &g.patient}, {"stylus", &g.stylus}};
  for (const auto& [key, name] : names) {
    s.text(key, *name);
    if constexpr (tracker_toml::kReads<Io>) {
      if (name->size() > 20) {  // OpenIGTLink's device and tool names are at most 20 bytes
        s.fail(key, "expected a device name of at most 20 characters (OpenIGTLink's limit), got \"" + *name + "\"");
      }
    }
  }
  if constexpr (tracker_toml::kReads<Io>) {
    if (g.head.empty() && g.patient.empty() && g.stylus.empty()) {
      s.fail("patient", "expected a device name for at least one of head, patient, stylus, got none");
    }
  }
  s.number("scale", g.scale, 1e-6, 1e6, "mm per unit");
  s.number("rigid_tolerance", g.rigid_tolerance, 1e-7, 0.5, "");
  s.number("connect_timeout_ms", g.connect_timeout_ms, 10.0, 60000.0, "ms");
  s.finish();
}

/// [trackers.plus].
template <class Io>
void visit(Io& s, PlusConfig& p) {
  const std::pair<const char*, std::string*> names[] = {
      {"head", &p.head}, {"patient", &p.patient}, {"stylus", &p.stylus}};
  for (const auto& [key, name] : names) {
    s.text(key, *name);
    if constexpr (tracker_toml::kReads<Io>) {
      // The tool is what comes before "To" in <Tool>To<Frame>Transform; OpenIGTLink carries <Tool>To<Frame> in 20.
      if (name->empty() || name->size() > 17 || name->find("To") != std::string::npos ||
          name->find_first_of(" =") != std::string::npos) {
        s.fail(key,
               "expected a PLUS tool name of 1 to 17 characters without \"To\", spaces or '=' (such as "
               "\"Reference\"), got \"" +
                   *name + "\"");
      }
    }
  }
  if constexpr (tracker_toml::kReads<Io>) {
    if (p.head == p.patient || p.head == p.stylus || p.patient == p.stylus) {
      s.fail("patient", "expected a different tool for each of head, patient and stylus, got \"" + p.head + "\", \"" +
                            p.patient + "\", \"" + p.stylus + "\"");
    }
  }
  s.finish();
}

/// [trackers.report].
template <class Io>
void visit(Io& s, ReportConfig& r) {
  s.integer("report_id", r.report_id, -1, 255, "(-1: unnumbered reports)");
  s.integer("length", r.length, 1, 1024, "bytes");
  s.choice("endian", r.endian, kEndianNames);
  s.integer("station_offset", r.station_offset, -1, 1023, "bytes (-1: no station byte)");
  s.integer("time_offset", r.time_offset, -1, 1023, "bytes (-1: no device time)");
  s.integer("time_bits", r.time_bits, 16, 32, "bits");
  if constexpr (tracker_toml::kReads<Io>) {
    if (r.time_bits != 16 && r.time_bits != 32) {
      s.fail("time_bits", "expected 16 or 32, got " + std::to_string(r.time_bits));
    }
  }
  s.number("time_tick_us", r.time_tick_us, 1e-3, 1e6, "us");
  s.integer("position_offset", r.position_offset, 0, 1023, "bytes");
  s.choice("position_type", r.position_type, kFieldTypeNames);  // only a position may be "none"
  tracker_toml::frac_bits(s, "position_frac_bits", r.position_frac_bits, r.position_type);
  tracker_toml::scale(s, "position_scale", r.position_scale, "mm per unit");
  tracker_toml::axes(s, "position_components", r.position_components, "xyz", "x,-z,y");
  s.choice("orientation", r.orientation, kOrientationKindNames);
  s.integer("orientation_offset", r.orientation_offset, 0, 1023, "bytes");
  s.choice("orientation_type", r.orientation_type, kOrientationFieldTypeNames);
  tracker_toml::frac_bits(s, "orientation_frac_bits", r.orientation_frac_bits, r.orientation_type);
  tracker_toml::scale(s, "orientation_scale", r.orientation_scale, "per unit");
  if (r.orientation == OrientationKind::Quaternion) {
    tracker_toml::axes(s, "orientation_components", r.orientation_components, "wxyz", "x,y,z,w");
  } else {
    if constexpr (tracker_toml::kReads<Io>) {
      // Keep the default quaternion list from tripping the Euler check when only `orientation` changed.
      if (r.orientation_components == ReportConfig{}.orientation_components) r.orientation_components = "z,y,x";
    }
    tracker_toml::axes(s, "orientation_components", r.orientation_components, "xyz", "z,y,x");
  }
  s.text("euler_sequence", r.euler_sequence);
  if constexpr (tracker_toml::kReads<Io>) tracker_toml::check_report(s, r);
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

/// [trackers] and its tables.
template <class Io>
void visit(Io& s, TrackerConfig& t) {
  s.choice("source", t.source, kTrackerSourceNames);
  s.choice("mock_trajectory", t.mock_trajectory, {"static", "upright_to_supine", "head_orbit", "bedside"});
  s.number("mock_rate_hz", t.mock_rate_hz, 1.0, 2000.0, "Hz");
  s.number("mock_noise_mm", t.mock_noise_mm, 0.0, 100.0, "mm");
  s.number("mock_dropout", t.mock_dropout, 0.0, 1.0, "(probability)");
  s.text("replay_file", t.replay_file);
  s.boolean("replay_realtime", t.replay_realtime);
  s.boolean("replay_loop", t.replay_loop);
  s.boolean("replay_truncated", t.replay_truncated);
  s.number("stale_ms", t.stale_ms, 1.0, 10000.0, "ms");
  s.number("reopen_backoff_ms", t.reopen_backoff_ms, 1.0, 60000.0, "ms");
  s.number("quat_norm_tolerance", t.quat_norm_tolerance, 1e-6, 0.5, "");
  s.numbers("workspace_min_mm", t.workspace_min_mm, -1e5, 1e5, "mm");
  s.numbers("workspace_max_mm", t.workspace_max_mm, -1e5, 1e5, "mm");
  if constexpr (tracker_toml::kReads<Io>) tracker_toml::check_workspace(s, t);
  tracker_toml::axes(s, "axis_remap", t.axis_remap, "xyz", "x,-z,y");
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
    if constexpr (tracker_toml::kReads<Io>) {
      if (sensor->enabled) tracker_toml::check_sensor(sec, t.report, sensor, roles);
    }
  }
  if constexpr (tracker_toml::kReads<Io>) {
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
