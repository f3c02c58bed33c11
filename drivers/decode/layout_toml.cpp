/// @file layout_toml.cpp
/// @brief Serialises the layout keys (HID reports and OpenIGTLink device names) with full precision so that a
/// round trip gives the same layout.
#include "drivers/decode/layout_toml.h"

#include <sstream>

#include "config/settings_load.h"
#include "config/toml_writer.h"

namespace lungar::drivers {

namespace {

using config::toml_number;
using config::toml_string;

std::string vec(const std::array<double, 3>& v) {
  return "[" + toml_number(v[0]) + ", " + toml_number(v[1]) + ", " + toml_number(v[2]) + "]";
}

}  // namespace

std::string layout_to_toml(const config::TrackerSettings& t) {
  const config::ReportSettings& r = t.report;
  std::ostringstream o;
  o << "[trackers]\n"
    << "quat_norm_tolerance = " << toml_number(t.quat_norm_tolerance) << "\n"
    << "workspace_min_mm = " << vec(t.workspace_min_mm) << "\n"
    << "workspace_max_mm = " << vec(t.workspace_max_mm) << "\n"
    << "axis_remap = " << toml_string(t.axis_remap) << "\n"
    << "world_offset_mm = " << vec(t.world_offset_mm) << "\n\n"
    << "[trackers.report]\n"
    << "report_id = " << r.report_id << "\n"
    << "length = " << r.length << "\n"
    << "endian = \"" << to_string(r.endian) << "\"\n"
    << "station_offset = " << r.station_offset << "\n"
    << "time_offset = " << r.time_offset << "\n"
    << "time_bits = " << r.time_bits << "\n"
    << "time_tick_us = " << toml_number(r.time_tick_us) << "\n"
    << "position_offset = " << r.position_offset << "\n"
    << "position_type = \"" << to_string(r.position_type) << "\"\n"
    << "position_frac_bits = " << r.position_frac_bits << "\n"
    << "position_scale = " << toml_number(r.position_scale) << "\n"
    << "position_components = \"" << r.position_components << "\"\n"
    << "orientation = \"" << to_string(r.orientation) << "\"\n"
    << "orientation_offset = " << r.orientation_offset << "\n"
    << "orientation_type = \"" << to_string(r.orientation_type) << "\"\n"
    << "orientation_frac_bits = " << r.orientation_frac_bits << "\n"
    << "orientation_scale = " << toml_number(r.orientation_scale) << "\n"
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
  o << "\n[trackers.igtl]\nhost = " << toml_string(g.host) << "\nport = " << g.port
    << "\nhead = " << toml_string(g.head) << "\npatient = " << toml_string(g.patient)
    << "\nstylus = " << toml_string(g.stylus) << "\nscale = " << toml_number(g.scale)
    << "\nrigid_tolerance = " << toml_number(g.rigid_tolerance) << "\n";
  return o.str();
}

Result<config::TrackerSettings> layout_from_toml(const std::string& toml, const std::string& name) {
  auto r = config::load_settings_from_string(toml, name);
  if (!r) return fail(r.error());
  return r->trackers;
}

}  // namespace lungar::drivers
