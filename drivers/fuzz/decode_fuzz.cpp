/// @file decode_fuzz.cpp
/// @brief libFuzzer target: decode_report() on arbitrary bytes, under a layout picked from the input's first byte.
///
/// The layouts cover both endiannesses, every field type, quaternions and Euler angles, station and
/// fixed-offset sensors. Whatever the bytes, decoding must not crash and an accepted pose must be finite,
/// unit and inside the workspace.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "drivers/decode/decoder.h"

using namespace lungar;

namespace {

std::vector<drivers::ReportLayout> make_layouts() {
  std::vector<drivers::ReportLayout> out;
  const config::FieldType types[] = {config::FieldType::I16, config::FieldType::I32, config::FieldType::F32,
                                     config::FieldType::Fixed16, config::FieldType::Fixed32};
  for (int variant = 0; variant < 20; ++variant) {
    config::TrackerSettings t;
    config::ReportSettings& r = t.report;
    r.endian = variant % 2 ? config::Endian::Big : config::Endian::Little;
    r.position_type = types[variant % 5];
    r.orientation_type = types[(variant / 2) % 5];
    r.position_frac_bits = r.position_type == config::FieldType::Fixed16 ? 4 : 0;
    r.orientation_frac_bits = r.orientation_type == config::FieldType::Fixed16   ? 14
                              : r.orientation_type == config::FieldType::Fixed32 ? 30
                                                                                 : 0;
    r.orientation_scale = (r.orientation_type == config::FieldType::I16 || r.orientation_type == config::FieldType::I32)
                              ? 1.0 / 16384
                              : 1.0;
    r.length = 64;
    r.orientation_offset = 12;
    if (variant % 4 == 3) {
      r.orientation = config::OrientationKind::Euler;
      r.orientation_components = "z,-y,x";
      r.euler_sequence = variant % 8 == 3 ? "zyx" : "xzy";
    } else if (variant % 4 == 2) {
      r.orientation_components = "x,y,-z,w";
    }
    if (variant >= 10) {  // fixed offsets, unnumbered reports, a mirrored axis remap
      r.report_id = -1;
      r.station_offset = -1;
      r.time_offset = variant % 3 == 0 ? -1 : 60;
      r.time_bits = 16;
      t.head = {true, 0, 0};
      t.patient = {true, 0, 28};
      t.axis_remap = "x,-z,y";
      t.stylus = {false, 0, 0};
    }
    auto l = drivers::make_layout(t);
    if (!l.layout) std::abort();  // a layout this file builds is always valid
    out.push_back(*l.layout);
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<drivers::ReportLayout> layouts = make_layouts();
  if (size < 1) return 0;
  const drivers::ReportLayout& l = layouts[data[0] % layouts.size()];
  const auto r = drivers::decode_report(std::span<const std::uint8_t>(data + 1, size - 1), l);
  for (int k = 0; k < r.count; ++k) {
    const auto& p = r.poses[k];
    for (int i = 0; i < 3; ++i) {
      if (!(p.position_mm[i] >= l.workspace_min_mm[i] && p.position_mm[i] <= l.workspace_max_mm[i])) std::abort();
    }
    if (std::abs(drivers::quat::norm(p.orientation_wxyz) - 1.0) > 1e-9) std::abort();
  }
  if (r.error != drivers::DecodeError::None && r.count != 0) std::abort();
  drivers::DeviceClock clock;
  clock.advance(r.device_ticks, l.time_bits, l.time_tick_ns);
  return 0;
}
