/// @file report_layout.cpp
/// @brief LayoutConfig -> ReportLayout: parses component lists, builds the axis remap, checks bounds.
#include "drivers/decode/report_layout.h"

#include <algorithm>

namespace lungar::drivers {

int FieldFormat::bytes() const {
  if (type == FieldType::None) return 0;
  return (type == FieldType::I16 || type == FieldType::Fixed16) ? 2 : 4;
}

namespace {

template <std::size_t N>
bool components(const std::string& text, std::string_view letters, std::array<Component, N>& out) {
  auto axes = parse_signed_axes(text, letters);
  if (!axes || axes->size() > N) return false;
  for (std::size_t k = 0; k < axes->size(); ++k) out[k] = {(*axes)[k].index, (*axes)[k].sign};
  return true;
}

Eigen::Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

/// Checks that the station byte, the time and each enabled sensor's fields lie inside the report, and adds the
/// sensors to `l`; an error reads "trackers.<key>: what is wrong".
Status place_fields(const LayoutConfig& t, ReportLayout& l) {
  const ReportConfig& r = t.report;
  const int first = r.report_id >= 0 ? 1 : 0;
  auto inside = [&](int offset, int bytes) { return offset >= first && offset + bytes <= r.length; };
  if (r.station_offset >= 0 && !inside(r.station_offset, 1)) {
    return fail("trackers.report.station_offset: expected a byte inside the report");
  }
  if (r.time_offset >= 0 && !inside(r.time_offset, r.time_bits / 8)) {
    return fail("trackers.report.time_offset: expected the timestamp inside the report");
  }
  const std::pair<Role, const SensorConfig*> sensors[] = {
      {Role::Head, &t.head}, {Role::Patient, &t.patient}, {Role::Stylus, &t.stylus}};
  for (const auto& [role, s] : sensors) {
    if (!s->enabled) continue;
    const std::string name = to_string(role);
    const int rot_n = l.euler ? 3 : 4;
    if ((l.position.present() && !inside(s->offset + r.position_offset, 3 * l.position.bytes())) ||
        !inside(s->offset + r.orientation_offset, rot_n * l.orientation.bytes())) {
      return fail("trackers." + name + ".offset: expected the sensor's fields inside the report");
    }
    if (s->station < 0 || s->station > 255) return fail("trackers." + name + ".station: expected 0 to 255");
    for (int k = 0; r.station_offset >= 0 && k < l.sensor_count; ++k) {
      if (l.sensors[k].station == s->station) {
        return fail("trackers." + name + ".station: expected a station different from trackers." +
                    to_string(l.sensors[k].role) + "'s");
      }
    }
    l.sensors[l.sensor_count++] = {role, s->station, s->offset, vec(s->fixed_position_mm)};
  }
  if (l.sensor_count == 0) return fail("trackers.head: expected at least one enabled sensor");
  return ok();
}

}  // namespace

Result<WorldFrame> make_world_frame(const LayoutConfig& t) {
  WorldFrame w;
  std::array<Component, 3> remap{};
  if (!components(t.axis_remap, "xyz", remap)) {
    return fail("trackers.axis_remap: expected a signed permutation of x,y,z");
  }
  w.remap.setZero();
  for (int row = 0; row < 3; ++row) w.remap(row, remap[row].index) = remap[row].sign;
  // A mirror (det -1) changes handedness; M R M^T equals (-M) R (-M)^T, and -M is a proper rotation.
  const Eigen::Matrix3d proper = w.remap.determinant() < 0 ? Eigen::Matrix3d(-w.remap) : w.remap;
  w.remap_rotation = Eigen::Quaterniond(proper).normalized();
  w.offset_mm = vec(t.world_offset_mm);
  w.quat_norm_tolerance = t.quat_norm_tolerance;
  w.workspace_min_mm = vec(t.workspace_min_mm);
  w.workspace_max_mm = vec(t.workspace_max_mm);
  return w;
}

Result<ReportLayout> make_layout(const LayoutConfig& t) {
  const ReportConfig& r = t.report;
  auto fail = [](const std::string& key, const std::string& what) {
    return lungar::fail("trackers." + key + ": " + what);
  };
  ReportLayout l;
  l.report_id = r.report_id;
  l.length = r.length;
  l.big_endian = r.endian == Endian::Big;
  l.station_offset = r.station_offset;
  l.time_offset = r.time_offset;
  l.time_bits = r.time_bits;
  l.time_tick_ns = r.time_tick_us * 1000.0;
  l.position_offset = r.position_offset;
  l.position = {r.position_type, r.position_frac_bits, r.position_scale};
  l.euler = r.orientation == OrientationKind::Euler;
  l.orientation_offset = r.orientation_offset;
  l.orientation = {r.orientation_type, r.orientation_frac_bits, r.orientation_scale};

  if (r.length < 1 || r.length > 1024) return fail("report.length", "expected 1 to 1024 bytes");
  if (r.report_id < -1 || r.report_id > 255) return fail("report.report_id", "expected -1 to 255");
  if (r.time_bits != 16 && r.time_bits != 32) return fail("report.time_bits", "expected 16 or 32");
  if (!(r.time_tick_us > 0)) return fail("report.time_tick_us", "expected a positive tick");
  if (r.position_scale == 0 || r.orientation_scale == 0) return fail("report", "expected non-zero scales");
  if (r.orientation_type == FieldType::None) {
    return fail("report.orientation_type", "expected a field type: only the position may be \"none\"");
  }
  if (r.position_frac_bits < 0 || r.position_frac_bits > 31 || r.orientation_frac_bits < 0 ||
      r.orientation_frac_bits > 31) {
    return fail("report", "expected 0 to 31 fractional bits");
  }
  if (!components(r.position_components, "xyz", l.position_components)) {
    return fail("report.position_components", "expected a signed permutation of x,y,z");
  }
  if (!components(r.orientation_components, l.euler ? "xyz" : "wxyz", l.orientation_components)) {
    return fail("report.orientation_components", "expected a signed permutation of the components");
  }
  std::array<Component, 3> seq{};
  if (r.euler_sequence.size() != 3 ||
      !components(std::string{r.euler_sequence[0], ',', r.euler_sequence[1], ',', r.euler_sequence[2]}, "xyz", seq)) {
    return fail("report.euler_sequence", "expected three distinct axes");
  }
  for (int k = 0; k < 3; ++k) l.euler_sequence[k] = seq[k].index;
  auto world = make_world_frame(t);
  if (!world) return lungar::fail(world.error());
  l.world = *world;

  if (Status placed = place_fields(t, l); !placed) return lungar::fail(placed.error());
  return l;
}

}  // namespace lungar::drivers
