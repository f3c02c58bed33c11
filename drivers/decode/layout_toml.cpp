/// @file layout_toml.cpp
/// @brief Serialises the layout keys (HID reports and OpenIGTLink device names) with full precision so that a
/// round trip gives the same layout.
#include "drivers/decode/layout_toml.h"

#include <cstdio>
#include <sstream>

#include "config/settings_load.h"

namespace lungar::drivers {

namespace {

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";  // keep TOML floats floats
  return s;
}

/// A TOML basic string: quotes and backslashes escaped, control characters as \uXXXX.
std::string quoted(const std::string& v) {
  std::string out = "\"";
  for (char c : v) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string vec(const std::array<double, 3>& v) { return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]"; }

}  // namespace

std::string layout_to_toml(const config::TrackerSettings& t) {
  const config::ReportSettings& r = t.report;
  std::ostringstream o;
  o << "[trackers]\n"
    << "quat_norm_tolerance = " << num(t.quat_norm_tolerance) << "\n"
    << "workspace_min_mm = " << vec(t.workspace_min_mm) << "\n"
    << "workspace_max_mm = " << vec(t.workspace_max_mm) << "\n"
    << "axis_remap = " << quoted(t.axis_remap) << "\n"
    << "world_offset_mm = " << vec(t.world_offset_mm) << "\n\n"
    << "[trackers.report]\n"
    << "report_id = " << r.report_id << "\n"
    << "length = " << r.length << "\n"
    << "endian = \"" << to_string(r.endian) << "\"\n"
    << "station_offset = " << r.station_offset << "\n"
    << "time_offset = " << r.time_offset << "\n"
    << "time_bits = " << r.time_bits << "\n"
    << "time_tick_us = " << num(r.time_tick_us) << "\n"
    << "position_offset = " << r.position_offset << "\n"
    << "position_type = \"" << to_string(r.position_type) << "\"\n"
    << "position_frac_bits = " << r.position_frac_bits << "\n"
    << "position_scale = " << num(r.position_scale) << "\n"
    << "position_components = \"" << r.position_components << "\"\n"
    << "orientation = \"" << to_string(r.orientation) << "\"\n"
    << "orientation_offset = " << r.orientation_offset << "\n"
    << "orientation_type = \"" << to_string(r.orientation_type) << "\"\n"
    << "orientation_frac_bits = " << r.orientation_frac_bits << "\n"
    << "orientation_scale = " << num(r.orientation_scale) << "\n"
    << "orientation_components = \"" << r.orientation_components << "\"\n"
    << "euler_sequence = \"" << r.euler_sequence << "\"\n";
  const std::pair<const char*, const config::SensorSettings*> sensors[] = {
      {"head", &t.head}, {"patient", &t.patient}, {"stylus", &t.stylus}};
  for (const auto& [name, s] : sensors) {
    o << "\n[trackers." << name << "]\nenabled = " << (s->enabled ? "true" : "false") << "\nstation = " << s->station
      << "\noffset = " << s->offset << "\nfixed_position_mm = " << vec(s->fixed_position_mm) << "\n";
  }
  // What an OpenIGTLink message decodes with: which device feeds which role, units, the rigidity tolerance.
  const config::IgtlSettings& g = t.igtl;
  o << "\n[trackers.igtl]\nhost = " << quoted(g.host) << "\nport = " << g.port << "\nhead = " << quoted(g.head)
    << "\npatient = " << quoted(g.patient) << "\nstylus = " << quoted(g.stylus) << "\nscale = " << num(g.scale)
    << "\nrigid_tolerance = " << num(g.rigid_tolerance) << "\n";
  return o.str();
}

Result<config::TrackerSettings> layout_from_toml(const std::string& toml, const std::string& name) {
  return config::load_tracker_settings_from_string(toml, name);
}

}  // namespace lungar::drivers
