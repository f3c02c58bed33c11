/// @file igtl_decoder.cpp
/// @brief OpenIGTLink header, CRC and TRANSFORM / TDATA / QTDATA bodies through libopenigtlink's C layer
/// (igtlutil), which reads in place: no message objects, so nothing is allocated per message.
#include "drivers/igtl/igtl_decoder.h"

#include <igtl_header.h>
#include <igtl_qtdata.h>
#include <igtl_tdata.h>
#include <igtl_transform.h>
#include <igtl_util.h>

#include <cstring>

namespace lungar::drivers {

static_assert(kIgtlHeaderBytes == IGTL_HEADER_SIZE && sizeof(igtl_header) == IGTL_HEADER_SIZE);
static_assert(sizeof(igtl_tdata_element) == IGTL_TDATA_ELEMENT_SIZE);
static_assert(sizeof(igtl_qtdata_element) == IGTL_QTDATA_ELEMENT_SIZE);

namespace {

enum class Kind { Transform, Tdata, Qtdata, Other };

Kind kind_of(const igtl_header& h) {
  if (std::strncmp(h.name, "TRANSFORM", IGTL_HEADER_TYPE_SIZE) == 0) return Kind::Transform;
  if (std::strncmp(h.name, "TDATA", IGTL_HEADER_TYPE_SIZE) == 0) return Kind::Tdata;
  if (std::strncmp(h.name, "QTDATA", IGTL_HEADER_TYPE_SIZE) == 0) return Kind::Qtdata;
  return Kind::Other;
}

/// The header in host byte order.
igtl_header read_header(const std::uint8_t* bytes) {
  igtl_header h;
  std::memcpy(&h, bytes, IGTL_HEADER_SIZE);
  igtl_header_convert_byte_order(&h);
  return h;
}

/// Whether `body_size` bytes hold whole elements of `kind` (and fit lungar's buffer).
bool body_fits(Kind kind, std::uint64_t body_size) {
  if (body_size == 0 || body_size > kIgtlMaxBody) return false;
  switch (kind) {
    case Kind::Transform:
      return body_size == IGTL_TRANSFORM_SIZE;
    case Kind::Tdata:
      return body_size % IGTL_TDATA_ELEMENT_SIZE == 0;
    case Kind::Qtdata:
      return body_size % IGTL_QTDATA_ELEMENT_SIZE == 0;
    case Kind::Other:
      break;
  }
  return false;
}

/// The role a device or tool name feeds, or -1. `name` holds up to 20 bytes, NUL-padded when shorter.
int role_of(const char* name, const IgtlLayout& l) {
  for (std::size_t r = 0; r < kRoleCount; ++r) {
    if (l.device[r][0] != '\0' && std::strncmp(name, l.device[r].data(), IGTL_HEADER_NAME_SIZE) == 0) {
      return static_cast<int>(r);
    }
  }
  return -1;
}

/// `n` floats from `p` (inside packed, unaligned structs: copied, never dereferenced as float*).
template <std::size_t N>
std::array<igtl_float32, N> floats(const void* p) {
  std::array<igtl_float32, N> out;
  std::memcpy(out.data(), p, sizeof out);
  return out;
}

/// A TRANSFORM matrix (12 floats: the rotation column by column, then the translation) as a world pose.
DecodeError pose_from_matrix(const void* matrix, const IgtlLayout& l, PoseSample& out) {
  const auto t = floats<12>(matrix);
  Eigen::Matrix3d r;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) r(i, j) = t[3 * j + i];
  }
  const Eigen::Vector3d p = Eigen::Vector3d(t[9], t[10], t[11]) * l.scale;
  if (!r.allFinite() || !p.allFinite()) return DecodeError::NotFinite;
  // A scaled, sheared or mirrored matrix (an ImageToProbe calibration, a hand-edited transform) is no pose.
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > l.rigid_tolerance ||
      !(r.determinant() > 0)) {
    return DecodeError::NotRigid;
  }
  return to_world(p, Eigen::Quaterniond(r), l.world, out);
}

DecodeError pose_from_quaternion(const void* position_xyz, const void* quaternion_xyzw, const IgtlLayout& l,
                                 PoseSample& out) {
  const auto position = floats<3>(position_xyz);
  const auto xyzw = floats<4>(quaternion_xyzw);
  const Eigen::Vector3d p = Eigen::Vector3d(position[0], position[1], position[2]) * l.scale;
  return to_world(p, Eigen::Quaterniond(xyzw[3], xyzw[0], xyzw[1], xyzw[2]), l.world, out);
}

/// One element (device or tool): its pose into `r` when its name feeds a role, else counted as ignored.
template <typename Decode>
DecodeError add_element(const char* name, const IgtlLayout& l, DecodedReport& r, Decode&& decode) {
  const int role = role_of(name, l);
  bool taken = false;
  for (int k = 0; k < r.count; ++k) taken = taken || static_cast<int>(r.poses[k].role) == role;
  if (role < 0 || taken) {  // an unmapped name, or a second element for a role already filled
    if (r.ignored++ == 0) std::memcpy(r.ignored_name.data(), name, IGTL_HEADER_NAME_SIZE);
    return DecodeError::None;
  }
  PoseSample& pose = r.poses[r.count];
  pose.role = static_cast<Role>(role);
  const DecodeError e = decode(pose);
  if (e == DecodeError::None) ++r.count;
  return e;
}

DecodeError decode_body(Kind kind, const igtl_header& h, std::uint8_t* body, std::size_t n, const IgtlLayout& l,
                        DecodedReport& r) {
  switch (kind) {
    case Kind::Transform: {
      auto* t = reinterpret_cast<igtl_float32*>(body);
      igtl_transform_convert_byte_order(t);
      return add_element(h.device_name, l, r, [&](PoseSample& p) { return pose_from_matrix(t, l, p); });
    }
    case Kind::Tdata: {
      auto* e = reinterpret_cast<igtl_tdata_element*>(body);
      const int count = static_cast<int>(n / IGTL_TDATA_ELEMENT_SIZE);
      igtl_tdata_convert_byte_order(e, count);
      for (int k = 0; k < count; ++k) {
        const DecodeError err =
            add_element(e[k].name, l, r, [&](PoseSample& p) { return pose_from_matrix(e[k].transform, l, p); });
        if (err != DecodeError::None) return err;
      }
      return DecodeError::None;
    }
    case Kind::Qtdata: {
      auto* e = reinterpret_cast<igtl_qtdata_element*>(body);
      const int count = static_cast<int>(n / IGTL_QTDATA_ELEMENT_SIZE);
      igtl_qtdata_convert_byte_order(e, count);
      for (int k = 0; k < count; ++k) {
        const DecodeError err = add_element(
            e[k].name, l, r, [&](PoseSample& p) { return pose_from_quaternion(e[k].position, e[k].quaternion, l, p); });
        if (err != DecodeError::None) return err;
      }
      return DecodeError::None;
    }
    case Kind::Other:
      break;
  }
  return DecodeError::UnknownType;
}

}  // namespace

Result<IgtlLayout> make_igtl_layout(const IgtlConfig& igtl, const LayoutConfig& world_settings) {
  IgtlLayout l;
  const std::pair<const char*, const std::string*> names[] = {
      {"head", &igtl.head}, {"patient", &igtl.patient}, {"stylus", &igtl.stylus}};
  for (std::size_t r = 0; r < kRoleCount; ++r) {
    const std::string& name = *names[r].second;
    if (name.size() > IGTL_HEADER_NAME_SIZE) {
      return fail(std::string("trackers.igtl.") + names[r].first + ": expected at most 20 characters, got \"" + name +
                  "\"");
    }
    std::memcpy(l.device[r].data(), name.data(), name.size());
  }
  if (!(igtl.scale > 0 && igtl.scale < 1e7)) return fail("trackers.igtl.scale: expected a positive scale");
  if (!(igtl.rigid_tolerance > 0)) return fail("trackers.igtl.rigid_tolerance: expected a positive tolerance");
  l.scale = igtl.scale;
  l.rigid_tolerance = igtl.rigid_tolerance;
  auto world = make_world_frame(world_settings);
  if (!world) return Error{world.error()};
  l.world = *world;
  return l;
}

IgtlHeaderInfo igtl_header_info(std::span<const std::uint8_t, kIgtlHeaderBytes> header) {
  const igtl_header h = read_header(header.data());
  IgtlHeaderInfo info;
  info.body_size = h.body_size;
  const Kind kind = kind_of(h);
  info.readable = h.version == IGTL_HEADER_VERSION && kind != Kind::Other && h.body_size <= kIgtlMaxBody;
  return info;
}

DecodedReport decode_igtl_message(std::span<const std::uint8_t> bytes, const IgtlLayout& l) {
  DecodedReport r;
  r.time_bits = 64;
  r.time_tick_ns = 1.0;
  auto fail = [&](DecodeError e) {
    r.error = e;
    r.count = 0;
    return r;
  };
  if (bytes.size() < IGTL_HEADER_SIZE) return fail(DecodeError::Truncated);
  const igtl_header h = read_header(bytes.data());
  if (h.version != IGTL_HEADER_VERSION) return fail(DecodeError::UnsupportedVersion);
  const Kind kind = kind_of(h);
  if (kind == Kind::Other) return fail(DecodeError::UnknownType);
  const std::size_t n = bytes.size() - IGTL_HEADER_SIZE;
  if (n != h.body_size) return fail(DecodeError::Truncated);
  if (!body_fits(kind, h.body_size)) return fail(DecodeError::WrongLength);
  alignas(8) std::array<std::uint8_t, kIgtlMaxBody> body;  // the C layer converts byte order in place
  std::memcpy(body.data(), bytes.data() + IGTL_HEADER_SIZE, n);
  if (crc64(body.data(), n, 0) != h.crc) return fail(DecodeError::BadCrc);
  if (h.timestamp != 0) {
    r.has_time = true;
    const auto frac = static_cast<igtl_uint32>(h.timestamp & 0xFFFFFFFFu);
    r.device_ticks = (h.timestamp >> 32) * 1'000'000'000ull + igtl_frac_to_nanosec(frac);
  }
  const DecodeError e = decode_body(kind, h, body.data(), n, l, r);
  if (e != DecodeError::None) return fail(e);
  return r;
}

}  // namespace lungar::drivers
