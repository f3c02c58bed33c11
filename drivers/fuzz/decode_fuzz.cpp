/// @file decode_fuzz.cpp
/// @brief libFuzzer target: random report layouts through make_layout(), then decode_report() on random bytes.
///
/// The first 12 bytes of the input describe a layout (types, endianness, fixed-point bits, offsets, lengths,
/// component orders and signs, Euler sequence, axis remap, station or fixed-offset sensors); the rest is the
/// report. Properties: make_layout() either rejects a layout or returns one that decode_report() can use on
/// any bytes without reading out of bounds (ASan checks); an accepted pose is finite, unit and inside the
/// workspace; a rejected report carries no pose; the encoder's output for a decoded pose decodes again.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "drivers/decode/decoder.h"
#include "drivers/decode/encoder.h"

using namespace lungar;

namespace {

const char* const kPerms3[] = {"x,y,z", "x,z,y", "y,x,z", "y,z,x", "z,x,y", "z,y,x"};
const char* const kPerms4[] = {"w,x,y,z", "x,y,z,w", "w,z,y,x", "z,w,x,y"};
const char* const kSeqs[] = {"zyx", "xyz", "yxz", "zxy", "xzy", "yzx", "zyz"};  // the last is invalid

std::string signed_perm(const char* perm, std::uint8_t signs) {
  std::string out;
  int k = 0;
  for (const char* p = perm; *p; ++p) {
    if (*p == ',') {
      out += ',';
      continue;
    }
    if (signs & (1u << k++)) out += '-';
    out += *p;
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 12) return 0;
  const std::uint8_t* c = data;
  drivers::LayoutConfig t;
  drivers::ReportConfig& r = t.report;
  const drivers::FieldType types[] = {drivers::FieldType::I16, drivers::FieldType::I32, drivers::FieldType::F32,
                                     drivers::FieldType::Fixed16, drivers::FieldType::Fixed32};
  r.endian = c[0] & 1 ? drivers::Endian::Big : drivers::Endian::Little;
  r.report_id = (c[0] & 2) ? -1 : c[1];
  r.position_type = types[(c[0] >> 2) % 5];
  r.orientation_type = types[(c[0] >> 5) % 5];
  r.position_frac_bits = c[2] % 33;  // up to 32: one past the valid range
  r.orientation_frac_bits = c[3] % 33;
  r.length = 1 + c[4] % 80;
  r.station_offset = static_cast<int>(c[5] % 82) - 1;
  r.time_offset = static_cast<int>(c[6] % 82) - 1;
  r.time_bits = c[6] & 0x80 ? 16 : 32;
  r.position_offset = c[7] % 40;
  r.orientation_offset = c[8] % 40;
  r.orientation = c[9] & 1 ? drivers::OrientationKind::Euler : drivers::OrientationKind::Quaternion;
  r.position_components = signed_perm(kPerms3[(c[9] >> 1) % 6], c[10]);
  r.orientation_components = r.orientation == drivers::OrientationKind::Euler
                                 ? signed_perm(kPerms3[(c[9] >> 4) % 6], c[10] >> 3)
                                 : signed_perm(kPerms4[(c[9] >> 4) % 4], c[10] >> 3);
  r.euler_sequence = kSeqs[c[11] % 7];
  r.position_scale = (c[11] & 0x80) ? 0.01 : 1.0;
  r.orientation_scale = (r.orientation_type == drivers::FieldType::I16) ? 1.0 / 16384 : 1.0;
  t.axis_remap = signed_perm(kPerms3[(c[11] >> 3) % 6], c[7] >> 5);
  t.head = {true, c[1] & 3, c[2] % 48, {}};
  t.patient = {(c[3] & 0x40) != 0, (c[1] >> 2) & 3, c[8] % 48, {}};
  t.stylus = {(c[3] & 0x80) != 0, (c[1] >> 4) & 3, c[5] % 48, {}};
  const auto made = drivers::make_layout(t);
  if (!made) {
    if (made.error().empty()) std::abort();
    return 0;
  }
  const drivers::ReportLayout& l = *made;
  const std::span<const std::uint8_t> report(data + 12, size - 12);
  const auto d = drivers::decode_report(report, l);
  if (d.error != drivers::DecodeError::None && d.count != 0) std::abort();
  for (int k = 0; k < d.count; ++k) {
    const auto& p = d.poses[k];
    for (int i = 0; i < 3; ++i) {
      if (!(p.position_mm[i] >= l.world.workspace_min_mm[i] && p.position_mm[i] <= l.world.workspace_max_mm[i])) {
        std::abort();
      }
    }
    if (std::abs(p.orientation().norm() - 1.0) > 1e-9) std::abort();
  }
  if (d.count > 0) {  // re-encode what was decoded (no crash, no undefined conversion)
    std::vector<std::uint8_t> again(static_cast<std::size_t>(l.length));
    if (!drivers::encode_report(l, std::span<const drivers::PoseSample>(d.poses.data(), d.count), d.device_ticks,
                                again)) {
      std::abort();
    }
    (void)drivers::decode_report(again, l);
  }
  drivers::DeviceClock clock;
  clock.advance(d.device_ticks, l.time_bits, l.time_tick_ns);
  clock.advance(d.device_ticks ^ 0x8001u, l.time_bits, l.time_tick_ns);
  return 0;
}
