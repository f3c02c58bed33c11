/// @file pose_sample.h
/// @brief One tracked pose as the frame loop sees it: role, device and arrival times, position, orientation.
/// @ingroup drivers
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

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

/// A pose in the world frame (millimetres, world +z up). Trivially copyable: it travels through seqlocks.
struct PoseSample {
  Role role = Role::Head;
  std::uint32_t flags = 0;
  std::int64_t t_device_ns = 0;   ///< device clock, unwrapped, from the first report of the session
  std::int64_t t_arrival_ns = 0;  ///< CLOCK_MONOTONIC when the report was read
  std::array<double, 3> position_mm = {0.0, 0.0, 0.0};
  std::array<double, 4> orientation_wxyz = {1.0, 0.0, 0.0, 0.0};  ///< unit quaternion, sensor -> world

  bool valid() const { return (flags & kPoseValid) != 0; }
  bool stale() const { return (flags & kPoseStale) != 0; }
};

}  // namespace lungar::drivers
