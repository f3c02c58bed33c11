/// @file settings_load.cpp
/// @brief The schema of [trackers]: which keys exist, their types, ranges and units, and the checks across them.
#include "config/settings_load.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/toml_section.h"

namespace lungar::config {

namespace {

std::size_t field_bytes(FieldType t) {
  if (t == FieldType::None) return 0;
  return (t == FieldType::I16 || t == FieldType::Fixed16) ? 2 : 4;
}

/// A field type; only a position may be "none" (an orientation-only report).
void read_field_type(TomlSection& s, const std::string& key, FieldType& out, bool may_be_none) {
  if (may_be_none) {
    s.choice(key, out, kFieldTypeNames);
  } else {
    s.choice(key, out, kOrientationFieldTypeNames);
  }
}

void read_frac_bits(TomlSection& s, const std::string& key, int& out, FieldType type) {
  s.integer(key, out, 0, 31, "bits");
  const int max = type == FieldType::Fixed16 ? 15 : type == FieldType::Fixed32 ? 31 : 0;
  if (out > max) {
    s.fail(key, "expected at most " + std::to_string(max) + " fractional bits for a " + to_string(type) +
                    " field, got " + std::to_string(out));
  }
}

void read_axes(TomlSection& s, const std::string& key, std::string& out, std::string_view letters,
               const std::string& example) {
  s.text(key, out);
  if (!parse_signed_axes(out, letters)) {
    s.fail(key, "expected each of " + std::string(letters) + " once, comma-separated, each optionally negated (e.g. \"" +
                    example + "\"), got \"" + out + "\"");
  }
}

void read_report(TomlSection s, ReportSettings& r) {
  s.integer("report_id", r.report_id, -1, 255, "(-1: unnumbered reports)");
  s.integer("length", r.length, 1, 1024, "bytes");
  s.choice("endian", r.endian, kEndianNames);
  s.integer("station_offset", r.station_offset, -1, 1023, "bytes (-1: no station byte)");
  s.integer("time_offset", r.time_offset, -1, 1023, "bytes (-1: no device time)");
  s.integer("time_bits", r.time_bits, 16, 32, "bits");
  if (r.time_bits != 16 && r.time_bits != 32) {
    s.fail("time_bits", "expected 16 or 32, got " + std::to_string(r.time_bits));
  }
  s.number("time_tick_us", r.time_tick_us, 1e-3, 1e6, "us");
  s.integer("position_offset", r.position_offset, 0, 1023, "bytes");
  read_field_type(s, "position_type", r.position_type, true);
  read_frac_bits(s, "position_frac_bits", r.position_frac_bits, r.position_type);
  s.number("position_scale", r.position_scale, -1e6, 1e6, "mm per unit");
  if (r.position_scale == 0.0) s.fail("position_scale", "expected a non-zero scale, got 0");
  read_axes(s, "position_components", r.position_components, "xyz", "x,-z,y");
  s.choice("orientation", r.orientation, kOrientationKindNames);
  s.integer("orientation_offset", r.orientation_offset, 0, 1023, "bytes");
  read_field_type(s, "orientation_type", r.orientation_type, false);
  read_frac_bits(s, "orientation_frac_bits", r.orientation_frac_bits, r.orientation_type);
  s.number("orientation_scale", r.orientation_scale, -1e6, 1e6, "per unit");
  if (r.orientation_scale == 0.0) s.fail("orientation_scale", "expected a non-zero scale, got 0");
  if (r.orientation == OrientationKind::Quaternion) {
    read_axes(s, "orientation_components", r.orientation_components, "wxyz", "x,y,z,w");
  } else {
    // Keep the default quaternion list from tripping the Euler check when only `orientation` changed.
    if (r.orientation_components == ReportSettings{}.orientation_components) r.orientation_components = "z,y,x";
    read_axes(s, "orientation_components", r.orientation_components, "xyz", "z,y,x");
  }
  s.text("euler_sequence", r.euler_sequence);
  if (r.euler_sequence.size() != 3 || !parse_signed_axes(std::string{r.euler_sequence[0], ',', r.euler_sequence[1], ',',
                                                                     r.euler_sequence[2]},
                                                         "xyz")) {
    s.fail("euler_sequence", "expected three distinct axes among x, y, z (e.g. \"zyx\"), got \"" + r.euler_sequence + "\"");
  }
  const int first = r.report_id >= 0 ? 1 : 0;  // byte 0 is the report id when reports are numbered
  auto inside = [&](const std::string& key, int offset, std::size_t bytes) {
    if (offset < first || offset + static_cast<int>(bytes) > r.length) {
      s.fail(key, "expected " + std::to_string(bytes) + " byte(s) at offset " + std::to_string(offset) +
                      " to lie within the report (bytes " + std::to_string(first) + " to " +
                      std::to_string(r.length - 1) + ")");
    }
  };
  if (r.station_offset >= 0) inside("station_offset", r.station_offset, 1);
  if (r.time_offset >= 0) inside("time_offset", r.time_offset, static_cast<std::size_t>(r.time_bits / 8));
  s.finish();
}

void read_sensor(TomlSection s, SensorSettings& d) {
  s.boolean("enabled", d.enabled);
  s.integer("station", d.station, 0, 255, "(station byte value)");
  s.integer("offset", d.offset, 0, 1023, "bytes");
  s.numbers("fixed_position_mm", d.fixed_position_mm, -1e5, 1e5, "mm");
  s.finish();
}

/// "0x02 0x01", "02 01" or "0x02,0x01": one to 4096 bytes, each one or two hex digits with an optional 0x.
std::optional<std::vector<std::uint8_t>> parse_hex_bytes(std::string_view text) {
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
      value = value * 16 + (std::isdigit(static_cast<unsigned char>(text[pos])) ? text[pos] - '0'
                                                                                : (text[pos] | 0x20) - 'a' + 10);
    }
    if (digits < 1 || digits > 2 || (pos < text.size() && text[pos] != ' ' && text[pos] != ',')) return std::nullopt;
    out.push_back(static_cast<std::uint8_t>(value));
  }
  if (out.empty() || out.size() > 4096) return std::nullopt;
  return out;
}

void read_hid(TomlSection hid, HidSettings& h) {
  hid.integer("vendor_id", h.vendor_id);
  hid.integer("product_id", h.product_id);
  hid.text("serial", h.serial);
  hid.text("path", h.path);
  hid.number("read_timeout_ms", h.read_timeout_ms, 1.0, 1000.0, "ms");
  std::vector<std::string> reports;
  hid.texts("init_feature_reports", reports);
  if (!reports.empty()) h.init_feature_reports.clear();
  for (std::size_t k = 0; k < reports.size(); ++k) {
    auto bytes = parse_hex_bytes(reports[k]);
    if (!bytes) {
      hid.fail("init_feature_reports", "expected hex bytes, report id first (e.g. \"0x02 0x01\"), got \"" + reports[k] +
                                           "\" at index " + std::to_string(k));
    }
    h.init_feature_reports.push_back(std::move(*bytes));
  }
  hid.finish();
}

void read_igtl(TomlSection s, IgtlSettings& g) {
  s.text("host", g.host);
  if (g.host.empty()) s.fail("host", "expected a host name or address (e.g. \"127.0.0.1\"), got \"\"");
  s.integer("port", g.port, 1, 65535, "(TCP port)");
  const std::pair<const char*, std::string*> names[] = {
      {"head", &g.head}, {"patient", &g.patient}, {"stylus", &g.stylus}};
  for (const auto& [key, name] : names) {
    s.text(key, *name);
    if (name->size() > 20) {  // OpenIGTLink's device and tool names are at most 20 bytes
      s.fail(key, "expected a device name of at most 20 characters (OpenIGTLink's limit), got \"" + *name + "\"");
    }
  }
  if (g.head.empty() && g.patient.empty() && g.stylus.empty()) {
    s.fail("patient", "expected a device name for at least one of head, patient, stylus, got none");
  }
  s.number("scale", g.scale, 1e-6, 1e6, "mm per unit");
  s.number("rigid_tolerance", g.rigid_tolerance, 1e-7, 0.5, "");
  s.number("connect_timeout_ms", g.connect_timeout_ms, 10.0, 60000.0, "ms");
  s.finish();
}

}  // namespace

void read_tracker_settings(TomlSection s, TrackerSettings& t) {
  s.choice("source", t.source, kTrackerSourceNames);
  s.choice("mock_trajectory", t.mock_trajectory, {"static", "upright_to_supine", "head_orbit"});
  s.number("mock_rate_hz", t.mock_rate_hz, 1.0, 2000.0, "Hz");
  s.number("mock_noise_mm", t.mock_noise_mm, 0.0, 100.0, "mm");
  s.number("mock_dropout", t.mock_dropout, 0.0, 1.0, "(probability)");
  s.text("replay_file", t.replay_file);
  s.boolean("replay_realtime", t.replay_realtime);
  s.boolean("replay_loop", t.replay_loop);
  s.number("stale_ms", t.stale_ms, 1.0, 10000.0, "ms");
  s.number("reopen_backoff_ms", t.reopen_backoff_ms, 1.0, 60000.0, "ms");
  s.number("quat_norm_tolerance", t.quat_norm_tolerance, 1e-6, 0.5, "");
  s.numbers("workspace_min_mm", t.workspace_min_mm, -1e5, 1e5, "mm");
  s.numbers("workspace_max_mm", t.workspace_max_mm, -1e5, 1e5, "mm");
  for (int k = 0; k < 3; ++k) {
    if (!(t.workspace_min_mm[k] < t.workspace_max_mm[k])) {
      s.fail("workspace_max_mm", "expected every component above workspace_min_mm's, got " +
                                     std::to_string(t.workspace_max_mm[k]) + " <= " +
                                     std::to_string(t.workspace_min_mm[k]) + " at index " + std::to_string(k));
    }
  }
  read_axes(s, "axis_remap", t.axis_remap, "xyz", "x,-z,y");
  s.numbers("world_offset_mm", t.world_offset_mm, -1e5, 1e5, "mm");
  read_hid(s.section("hid"), t.hid);
  read_igtl(s.section("igtl"), t.igtl);
  read_report(s.section("report"), t.report);
  const std::pair<const char*, SensorSettings*> sensors[] = {
      {"head", &t.head}, {"patient", &t.patient}, {"stylus", &t.stylus}};
  for (const auto& [name, sensor] : sensors) {
    TomlSection sec = s.section(name);
    read_sensor(sec, *sensor);
    if (!sensor->enabled) continue;
    const ReportSettings& r = t.report;
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
    if (r.station_offset >= 0) {
      for (const auto& [other_name, other] : sensors) {
        if (other == sensor) break;
        if (other->enabled && other->station == sensor->station) {
          sec.fail("station", "expected a station different from trackers." + std::string(other_name) +
                                  "'s, got " + std::to_string(sensor->station) + " for both");
        }
      }
    }
  }
  if (!t.head.enabled && !t.patient.enabled && !t.stylus.enabled) {
    s.fail("head", "expected at least one of trackers.head, trackers.patient, trackers.stylus enabled, got none");
  }
  if (t.source == TrackerSource::Replay && t.replay_file.empty()) {
    s.fail("replay_file", "expected a .trk file when source = \"replay\", got nothing");
  }
  s.finish();
}

std::optional<std::vector<SignedAxis>> parse_signed_axes(std::string_view text, std::string_view letters) {
  std::vector<SignedAxis> out;
  std::vector<bool> seen(letters.size(), false);
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    std::string_view item = text.substr(pos, comma - pos);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    SignedAxis a;
    if (!item.empty() && (item.front() == '-' || item.front() == '+')) {
      a.sign = item.front() == '-' ? -1 : 1;
      item.remove_prefix(1);
    }
    if (item.size() != 1) return std::nullopt;
    const std::size_t index = letters.find(item.front());
    if (index == std::string_view::npos || seen[index]) return std::nullopt;
    seen[index] = true;
    a.index = static_cast<int>(index);
    out.push_back(a);
    pos = comma + 1;
  }
  if (out.size() != letters.size()) return std::nullopt;
  return out;
}

Result<TrackerSettings> load_tracker_settings_from_string(const std::string& toml_text, const std::string& name) {
  auto parsed = parse_toml(toml_text, name);
  if (!parsed) return parsed.with_context("");
  TrackerSettings t;
  try {
    TomlSection top(&*parsed, "", name);
    read_tracker_settings(top.section("trackers"), t);
  } catch (const ConfigError& e) {
    return fail(e.what());
  }
  return t;
}

Result<TrackerSettings> load_tracker_settings(const std::string& path) {
  auto text = read_toml_file(path, "config");
  if (!text) return text.with_context("");
  return load_tracker_settings_from_string(*text, path);
}

}  // namespace lungar::config
