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
  if (std::isnan(raw) && f.type != FieldType::F32) raw = 0;
  if (f.type == FieldType::F32 && std::abs(raw) > std::numeric_limits<float>::max()) {
    raw = std::copysign(std::numeric_limits<double>::infinity(), raw);
  }
  std::uint32_t u = 0;
  switch (f.type) {
    case FieldType::I16:
    case FieldType::Fixed16: {
      const double c = std::clamp(std::round(raw), -32768.0, 32767.0);
      u = static_cast<std::uint16_t>(static_cast<std::int16_t>(c));
      break;
    }
    case FieldType::I32:
    case FieldType::Fixed32: {
      const double c = std::clamp(std::round(raw), -2147483648.0, 2147483647.0);
      u = static_cast<std::uint32_t>(static_cast<std::int32_t>(c));
      break;
    }
    case FieldType::F32: u = std::bit_cast<std::uint32_t>(static_cast<float>(raw)); break;
    case FieldType::None: return;  // no field to write
  }
  write_uint(p, u, f.bytes(), big);
}

/// Tait-Bryan angles (radians, indexed by axis) with R = R_i(a_i) R_j(a_j) R_k(a_k) for the intrinsic sequence
/// (i, j, k), the middle one in [-pi/2, pi/2] as devices send them (Eigen's first angle is in [0, pi] instead).
Eigen::Vector3d euler_angles(const Eigen::Quaterniond& q, const std::array<int, 3>& seq) {
  Eigen::Vector3d e = q.toRotationMatrix().eulerAngles(seq[0], seq[1], seq[2]);
  if (std::abs(e[1]) > M_PI / 2) {  // the other solution of the same rotation: (a + pi, pi - b, c + pi)
    e[0] -= M_PI;
    e[1] = (e[1] > 0 ? M_PI : -M_PI) - e[1];
    e[2] += e[2] > 0 ? -M_PI : M_PI;
  }
  Eigen::Vector3d by_axis;
  for (int k = 0; k < 3; ++k) by_axis[seq[k]] = e[k];
  return by_axis;
}

void encode_sensor(std::uint8_t* block, const ReportLayout& l, const PoseSample& pose) {
  // World -> tracker: p = M^T (p' - offset), q = r* q' r.
  const WorldFrame& w = l.world;
  const Eigen::Vector3d device_pos = w.remap.transpose() * (pose.position() - w.offset_mm);
  for (int k = 0; l.position.present() && k < 3; ++k) {
    const Component c = l.position_components[k];
    write_field(block + l.position_offset + k * l.position.bytes(), c.sign * device_pos[c.index], l.position,
                l.big_endian);
  }
  const Eigen::Quaterniond q = w.remap_rotation.conjugate() * pose.orientation() * w.remap_rotation;
  std::uint8_t* op = block + l.orientation_offset;
  if (l.euler) {
    const Eigen::Vector3d a = euler_angles(q, l.euler_sequence);
    for (int k = 0; k < 3; ++k) {
      const Component c = l.orientation_components[k];
      write_field(op + k * l.orientation.bytes(), c.sign * a[c.index] * (180.0 / M_PI), l.orientation, l.big_endian);
    }
  } else {
    const Eigen::Vector4d wxyz(q.w(), q.x(), q.y(), q.z());
    for (int k = 0; k < 4; ++k) {
      const Component c = l.orientation_components[k];
      write_field(op + k * l.orientation.bytes(), c.sign * wxyz[c.index], l.orientation, l.big_endian);
    }
  }
}

}  // namespace

bool encode_report(const ReportLayout& l, std::span<const PoseSample> poses, std::uint32_t ticks,
                   std::span<std::uint8_t> out) {
  if (out.size() < static_cast<std::size_t>(l.length) || poses.empty()) return false;
  if (l.station_offset >= 0 && poses.size() != 1) return false;
  std::uint8_t* p = out.data();
  std::memset(p, 0, static_cast<std::size_t>(l.length));
  if (l.report_id >= 0) p[0] = static_cast<std::uint8_t>(l.report_id);
  if (l.time_offset >= 0) write_uint(p + l.time_offset, ticks, l.time_bits / 8, l.big_endian);
  for (const PoseSample& pose : poses) {
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
