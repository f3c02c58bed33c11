/// @file decoder.cpp
/// @brief Field reads (any endianness, integer, float and fixed point), component remapping, validation.
#include "drivers/decode/decoder.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace lungar::drivers {

const char* to_string(DecodeError e) {
  switch (e) {
    case DecodeError::None: return "ok";
    case DecodeError::WrongLength: return "wrong length";
    case DecodeError::UnknownReportId: return "unknown report id";
    case DecodeError::UnknownStation: return "unknown station";
    case DecodeError::NotFinite: return "NaN or infinity";
    case DecodeError::QuaternionNorm: return "quaternion norm off";
    case DecodeError::OutsideWorkspace: return "position outside the workspace";
    case DecodeError::TimeBackwards: return "device time ran backwards";
    case DecodeError::UnknownType: return "unknown message type";
    case DecodeError::BadCrc: return "CRC mismatch";
    case DecodeError::Truncated: return "truncated message";
    case DecodeError::NotRigid: return "transform not rigid";
    case DecodeError::UnsupportedVersion: return "unsupported header version";
  }
  return "?";
}

namespace {

std::uint32_t read_uint(const std::uint8_t* p, int bytes, bool big) {
  std::uint32_t v = 0;
  for (int k = 0; k < bytes; ++k) {
    const std::uint32_t b = p[big ? k : bytes - 1 - k];
    v = (v << 8) | b;
  }
  return v;
}

double read_field(const std::uint8_t* p, const FieldFormat& f, bool big) {
  const std::uint32_t u = read_uint(p, f.bytes(), big);
  double raw = 0;
  switch (f.type) {
    case FieldType::I16:
    case FieldType::Fixed16: raw = static_cast<std::int16_t>(static_cast<std::uint16_t>(u)); break;
    case FieldType::I32:
    case FieldType::Fixed32: raw = static_cast<std::int32_t>(u); break;
    case FieldType::F32: raw = std::bit_cast<float>(u); break;
    case FieldType::None: break;  // never read (FieldFormat::present())
  }
  return std::ldexp(raw, -f.frac_bits) * f.scale;
}

DecodeError decode_sensor(const std::uint8_t* report, const SensorLayout& sensor, const ReportLayout& l,
                          PoseSample& out) {
  const std::uint8_t* block = report + sensor.offset;
  Eigen::Vector3d device_pos = sensor.fixed_position_mm;  // an orientation-only sensor stays where it is mounted
  if (l.position.present()) {
    const std::uint8_t* pp = block + l.position_offset;
    for (int k = 0; k < 3; ++k) {
      const Component c = l.position_components[k];
      device_pos[c.index] = c.sign * read_field(pp + k * l.position.bytes(), l.position, l.big_endian);
    }
  }
  const std::uint8_t* op = block + l.orientation_offset;
  Eigen::Quaterniond q;
  if (l.euler) {
    Eigen::Vector3d angle_rad;  // indexed by axis
    for (int k = 0; k < 3; ++k) {
      const Component c = l.orientation_components[k];
      angle_rad[c.index] =
          c.sign * read_field(op + k * l.orientation.bytes(), l.orientation, l.big_endian) * (M_PI / 180.0);
    }
    if (!angle_rad.allFinite()) return DecodeError::NotFinite;
    const auto& s = l.euler_sequence;  // intrinsic: R = R_s0 R_s1 R_s2
    q = Eigen::AngleAxisd(angle_rad[s[0]], Eigen::Vector3d::Unit(s[0])) *
        Eigen::AngleAxisd(angle_rad[s[1]], Eigen::Vector3d::Unit(s[1])) *
        Eigen::AngleAxisd(angle_rad[s[2]], Eigen::Vector3d::Unit(s[2]));
  } else {
    Eigen::Vector4d wxyz;
    for (int k = 0; k < 4; ++k) {
      const Component c = l.orientation_components[k];
      wxyz[c.index] = c.sign * read_field(op + k * l.orientation.bytes(), l.orientation, l.big_endian);
    }
    q = Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  }
  return to_world(device_pos, q, l.world, out);
}

}  // namespace

DecodeError to_world(const Eigen::Vector3d& device_pos_mm, const Eigen::Quaterniond& q, const WorldFrame& w,
                     PoseSample& out) {
  if (!device_pos_mm.allFinite() || !q.coeffs().allFinite()) return DecodeError::NotFinite;
  const double n = q.norm();
  if (!std::isfinite(n)) return DecodeError::NotFinite;
  if (std::abs(n - 1.0) > w.quat_norm_tolerance) return DecodeError::QuaternionNorm;
  // Change of basis tracker -> world: p' = M p + offset, R' = M R M^T (= r q r* with r the proper part of M).
  const Eigen::Vector3d p = w.remap * device_pos_mm + w.offset_mm;
  if (!((p.array() >= w.workspace_min_mm.array()).all() && (p.array() <= w.workspace_max_mm.array()).all())) {
    return DecodeError::OutsideWorkspace;
  }
  Eigen::Quaterniond r = w.remap_rotation * Eigen::Quaterniond(q.coeffs() / n) * w.remap_rotation.conjugate();
  if (r.w() < 0) r.coeffs() = -r.coeffs();  // one sign per rotation, so equal reports compare equal
  out.set_position(p);
  out.set_orientation(r);
  return DecodeError::None;
}

DecodedReport decode_report(std::span<const std::uint8_t> bytes, const ReportLayout& l) {
  DecodedReport r;
  auto fail = [&](DecodeError e) {
    r.error = e;
    r.count = 0;
    return r;
  };
  if (bytes.size() != static_cast<std::size_t>(l.length)) return fail(DecodeError::WrongLength);
  const std::uint8_t* p = bytes.data();
  if (l.report_id >= 0 && p[0] != l.report_id) return fail(DecodeError::UnknownReportId);
  if (l.time_offset >= 0) {
    r.has_time = true;
    r.device_ticks = read_uint(p + l.time_offset, l.time_bits / 8, l.big_endian);
  }
  r.time_bits = l.time_bits;
  r.time_tick_ns = l.time_tick_ns;
  for (int k = 0; k < l.sensor_count; ++k) {
    const SensorLayout& s = l.sensors[k];
    if (l.station_offset >= 0 && p[l.station_offset] != s.station) continue;
    PoseSample& pose = r.poses[r.count];
    pose.role = s.role;
    const DecodeError e = decode_sensor(p, s, l, pose);
    if (e != DecodeError::None) return fail(e);
    ++r.count;
  }
  if (r.count == 0) return fail(DecodeError::UnknownStation);
  return r;
}

std::int64_t DeviceClock::advance(std::uint64_t ticks, int bits, double tick_ns) {
  const std::uint64_t mask = bits >= 64 ? ~0ull : (1ull << bits) - 1;
  ticks &= mask;
  if (!started_) {
    started_ = true;
    last_ = ticks;
    total_ticks_ = 0;
    return 0;
  }
  const std::uint64_t delta = (ticks - last_) & mask;  // modulo the counter's range
  if (delta > (mask >> 1) + 1) return -1;               // more than half the range: backwards, not a wrap
  last_ = ticks;
  constexpr std::int64_t kSaturated = 9'000'000'000'000'000'000;  // centuries of device time
  if (delta > static_cast<std::uint64_t>(kSaturated - total_ticks_)) return kSaturated;
  total_ticks_ += static_cast<std::int64_t>(delta);
  const double ns = static_cast<double>(total_ticks_) * tick_ns;
  return ns < 9e18 ? static_cast<std::int64_t>(ns) : kSaturated;
}

}  // namespace lungar::drivers
