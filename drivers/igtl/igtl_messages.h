/// @file igtl_messages.h
/// @brief OpenIGTLink messages packed by libopenigtlink's own message classes, as PlusServer and 3D Slicer send
/// them: what `lungar-trk serve-igtl` streams and what the tests feed the source and the decoder.
/// @ingroup drivers
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lungar::drivers {

/// One tool of a TDATA or QTDATA message. `matrix`: tool -> tracker, millimetres (any 4x4: tests send bad ones).
struct IgtlTool {
  std::string name;
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
};

/// The header timestamp of `unix_ns` (0: none).
struct IgtlTime {
  std::uint32_t seconds = 0, fraction = 0;
  static IgtlTime from_ns(std::uint64_t unix_ns);
};

/// A TRANSFORM message (igtl::TransformMessage): header and body, ready to send.
std::vector<std::uint8_t> igtl_transform_message(const std::string& device, const Eigen::Matrix4d& matrix,
                                                 IgtlTime time);
/// A TDATA message (igtl::TrackingDataMessage), one 6D element per tool.
std::vector<std::uint8_t> igtl_tdata_message(const std::string& device, std::span<const IgtlTool> tools, IgtlTime time);
/// A QTDATA message (igtl::QuaternionTrackingDataMessage): position and quaternion of each tool's matrix.
std::vector<std::uint8_t> igtl_qtdata_message(const std::string& device, std::span<const IgtlTool> tools,
                                              IgtlTime time);
/// A message of a type lungar does not read (a STATUS message, as servers send on connection).
std::vector<std::uint8_t> igtl_status_message(const std::string& device, IgtlTime time);

}  // namespace lungar::drivers
