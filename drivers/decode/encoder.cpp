/// @file encoder.cpp
/// @brief Inverse remap, component order, Euler extraction and field writes for synthetic reports.
#include "drivers/decode/encoder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace lungar::drivers {

namespace {

void write_uint(std::uint8_t* p, std::uint32_t v, int bytes, bool big) {
  for (int k = 0; k < bytes; ++k) {
    p[big ? bytes - 1 - k : k] = static_cast<std::uint8_t>(v >> (8 * k));
  }
}

void write_field(std::uint8_t* p, double value, const FieldFormat& f, bool big) {
  double raw = std::ldexp(value / f.scale, f.frac_bits);
  // Out-of-range conversions are undefined behaviour: NaN becomes 0 for integers, floats saturate to infinity.
  if (std::isnan(raw) && f.type != config::FieldType::F32) raw = 0;
  if (f.type == config::FieldType::F32 && std::abs(raw) > std::numeric_limits<float>::max()) {
    raw = std::copysign(std::numeric_limits<double>::infinity(), raw);
  }
  std::uint32_t u = 0;
  switch (f.type) {
    case config::FieldType::I16:
    case config::FieldType::Fixed16: {
      const double c = std::clamp(std::round(raw), -32768.0, 32767.0);
      u = static_cast<std::uint16_t>(static_cast<std::int16_t>(c));
      break;
    }
    case config::FieldType::I32:
    case config::FieldType::Fixed32: {
      const double c = std::clamp(std::round(raw), -2147483648.0, 2147483647.0);
      u = static_cast<std::uint32_t>(static_cast<std::int32_t>(c));
      break;
    }
    case config::FieldType::F32: u = std::bit_cast<std::uint32_t>(static_cast<float>(raw)); break;
  }
  write_uint(p, u, f.bytes(), big);
}

bool is_cyclic(const std::array<int, 3>& s) { return (s[1] - s[0] + 3) % 3 == 1; }

/// Angles (radians, indexed by axis) with R = R_i(a_i) R_j(a_j) R_k(a_k), for the intrinsic sequence (i, j, k).
quat::V euler_angles(const quat::Q& q, const std::array<int, 3>& seq) {
  const quat::M m = quat::to_matrix(q);
  const int i = seq[0], j = seq[1], k = seq[2];
  const double e = is_cyclic(seq) ? 1.0 : -1.0;
  quat::V a{};
  a[j] = std::asin(std::clamp(e * m[i][k], -1.0, 1.0));
  a[i] = std::atan2(-e * m[j][k], m[k][k]);
  a[k] = std::atan2(-e * m[i][j], m[i][i]);
  return a;
}

void encode_sensor(std::uint8_t* block, const ReportLayout& l, const DecodedPose& pose) {
  // World -> tracker: p = M^T (p' - offset), q = r* q' r.
  quat::V device_pos{};
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) device_pos[j] += l.remap[i][j] * (pose.position_mm[i] - l.world_offset_mm[i]);
  }
  for (int k = 0; k < 3; ++k) {
    const Component c = l.position_components[k];
    write_field(block + l.position_offset + k * l.position.bytes(), c.sign * device_pos[c.index], l.position,
                l.big_endian);
  }
  const quat::Q q = quat::mul(quat::mul(quat::conj(l.remap_rotation), pose.orientation_wxyz), l.remap_rotation);
  std::uint8_t* op = block + l.orientation_offset;
  if (l.euler) {
    const quat::V a = euler_angles(q, l.euler_sequence);
    for (int k = 0; k < 3; ++k) {
      const Component c = l.orientation_components[k];
      write_field(op + k * l.orientation.bytes(), c.sign * a[c.index] * (180.0 / M_PI), l.orientation, l.big_endian);
    }
  } else {
    for (int k = 0; k < 4; ++k) {
      const Component c = l.orientation_components[k];
      write_field(op + k * l.orientation.bytes(), c.sign * q[c.index], l.orientation, l.big_endian);
    }
  }
}

}  // namespace

bool encode_report(const ReportLayout& l, std::span<const DecodedPose> poses, std::uint32_t ticks,
                   std::span<std::uint8_t> out) {
  if (out.size() < static_cast<std::size_t>(l.length) || poses.empty()) return false;
  if (l.station_offset >= 0 && poses.size() != 1) return false;
  std::uint8_t* p = out.data();
  std::memset(p, 0, static_cast<std::size_t>(l.length));
  if (l.report_id >= 0) p[0] = static_cast<std::uint8_t>(l.report_id);
  if (l.time_offset >= 0) write_uint(p + l.time_offset, ticks, l.time_bits / 8, l.big_endian);
  for (const DecodedPose& pose : poses) {
    const SensorLayout* sensor = nullptr;
    for (int k = 0; k < l.sensor_count; ++k) {
      if (l.sensors[k].role == pose.role) sensor = &l.sensors[k];
    }
    if (!sensor) return false;
    if (l.station_offset >= 0) p[l.station_offset] = static_cast<std::uint8_t>(sensor->station);
    encode_sensor(p + sensor->offset, l, pose);
  }
  return true;
}

}  // namespace lungar::drivers
