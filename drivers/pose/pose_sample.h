/// @file pose_sample.h
/// @brief lungar's one pose type: role, device and arrival times, position and orientation, with Eigen accessors.
/// @ingroup drivers
///
/// Decoders, sources, the mailboxes, prediction and the runtime all pass this one struct. It travels through
/// seqlocks (mailbox.h), so it must stay trivially copyable: Eigen's fixed-size types are not, hence the plain
/// arrays as storage and position() / orientation() (and their setters) as the way callers read and write it.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace lungar::drivers {

/// What a sensor is fixed to. The values index per-role arrays.
enum class Role : std::uint8_t { Head = 0, Patient = 1, Stylus = 2 };
inline constexpr std::size_t kRoleCount = 3;
inline constexpr std::array<Role, kRoleCount> kRoles = {Role::Head, Role::Patient, Role::Stylus};

const char* to_string(Role role);
std::optional<Role> role_from_string(std::string_view name);

/// Bits of PoseSample::flags.
enum PoseFlag : std::uint32_t {
  kPoseValid = 1u << 0,      ///< a decoded, validated pose (a default sample has no flags)
  kPoseStale = 1u << 1,      ///< older than the configured stale age when it was read
  kPosePredicted = 1u << 2,  ///< extrapolated by constant velocity, not measured
  kPoseNoDeviceTime = 1u << 3,  ///< the report had no device time; t_device is the arrival time
};

/// A pose in the world frame (millimetres, world +z up).
struct PoseSample {
  Role role = Role::Head;
  std::uint32_t flags = 0;
  std::int64_t t_device_ns = 0;   ///< device clock, unwrapped, from the first report of the session
  std::int64_t t_arrival_ns = 0;  ///< CLOCK_MONOTONIC when the report was read
  std::array<double, 3> position_mm = {0.0, 0.0, 0.0};            ///< storage; read with position()
  std::array<double, 4> orientation_wxyz = {1.0, 0.0, 0.0, 0.0};  ///< storage; unit quaternion, sensor -> world

  bool valid() const { return (flags & kPoseValid) != 0; }
  bool stale() const { return (flags & kPoseStale) != 0; }

  Eigen::Vector3d position() const { return {position_mm[0], position_mm[1], position_mm[2]}; }
  /// Sensor -> world rotation (Hamilton, as stored: w first).
  Eigen::Quaterniond orientation() const {
    return {orientation_wxyz[0], orientation_wxyz[1], orientation_wxyz[2], orientation_wxyz[3]};
  }
  /// The rigid transform sensor -> world, millimetres (the orientation normalised: a hand-made sample may not be).
  Eigen::Isometry3d transform() const {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = orientation().normalized().toRotationMatrix();
    t.translation() = position();
    return t;
  }
  void set_position(const Eigen::Vector3d& p) { position_mm = {p.x(), p.y(), p.z()}; }
  void set_orientation(const Eigen::Quaterniond& q) { orientation_wxyz = {q.w(), q.x(), q.y(), q.z()}; }
};
static_assert(std::is_trivially_copyable_v<PoseSample>, "PoseSample travels through seqlock mailboxes");

}  // namespace lungar::drivers
