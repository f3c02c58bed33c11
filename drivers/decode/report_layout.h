/// @file report_layout.h
/// @brief The report layout in the form the decoder uses, converted once from LayoutConfig.
/// @ingroup drivers
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "config/base/result.h"
#include "drivers/decode/report_settings.h"
#include "drivers/pose/pose_sample.h"

namespace lungar::drivers {

/// How one number is read: type, fixed-point bits and scale. value = raw / 2^frac_bits * scale.
struct FieldFormat {
  FieldType type = FieldType::I16;
  int frac_bits = 0;
  double scale = 1.0;
  int bytes() const;  ///< 2 or 4; 0 for FieldType::None (no field in the report)
  bool present() const { return type != FieldType::None; }
};

/// One component the device sends: which axis (x,y,z = 0..2; quaternion w,x,y,z = 0..3) and its sign.
struct Component {
  int index = 0;
  int sign = 1;
};

struct SensorLayout {
  Role role = Role::Head;
  int station = 0;
  int offset = 0;
  Eigen::Vector3d fixed_position_mm = Eigen::Vector3d::Zero();  ///< tracker axes; used when the report has none
};

/// Tracker frame -> world frame, and what a world pose must satisfy: shared by every decoder (HID reports,
/// OpenIGTLink messages). p' = remap p + offset; q' = r q r* with r the proper part of remap.
struct WorldFrame {
  Eigen::Matrix3d remap = Eigen::Matrix3d::Identity();                ///< signed permutation, world <- tracker
  Eigen::Quaterniond remap_rotation = Eigen::Quaterniond::Identity();  ///< the proper rotation +-remap
  Eigen::Vector3d offset_mm = Eigen::Vector3d::Zero();
  double quat_norm_tolerance = 0.05;
  Eigen::Vector3d workspace_min_mm = Eigen::Vector3d::Zero(), workspace_max_mm = Eigen::Vector3d::Zero();
};

/// Everything decode_report() needs, resolved and checked: plain data, no allocation.
struct ReportLayout {
  int report_id = -1;
  int length = 0;
  bool big_endian = false;
  int station_offset = -1;
  int time_offset = -1;
  int time_bits = 32;
  double time_tick_ns = 1000.0;
  int position_offset = 0;
  FieldFormat position;
  std::array<Component, 3> position_components{};
  bool euler = false;
  int orientation_offset = 0;
  FieldFormat orientation;
  std::array<Component, 4> orientation_components{};  ///< 3 used for Euler angles
  std::array<int, 3> euler_sequence = {2, 1, 0};
  WorldFrame world;
  std::array<SensorLayout, kRoleCount> sensors{};
  int sensor_count = 0;
};

/// The world frame of the [trackers] keys (axis_remap, world_offset_mm, workspace, quat_norm_tolerance); an
/// error names the key. make_layout() uses it; other decoders (OpenIGTLink) too.
Result<WorldFrame> make_world_frame(const LayoutConfig& t);

/// Converts and checks the tracker settings (the loader checks them too; this guards hand-made settings); an error
/// reads "trackers.<key>: expected ..., got ...".
Result<ReportLayout> make_layout(const LayoutConfig& t);

}  // namespace lungar::drivers
