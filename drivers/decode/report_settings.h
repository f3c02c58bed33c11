/// @file report_settings.h
/// @brief The decoder's settings: [trackers.report] (the byte layout of a report), the sensors' tables and the
/// world frame, with the names TOML spells their enumerations with. Beside the decoder that reads them;
/// tracker_config.h composes them into [trackers].
/// @ingroup drivers
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/base/enum_names.h"

namespace lungar::drivers {

// Each enumeration with the names TOML, the command line and logs spell it with: one table each.

/// How one number is stored in a report. None (position only): the report carries no position (an
/// orientation-only sensor such as an HMD's IMU); each role then uses its fixed_position_mm.
enum class FieldType { I16, I32, F32, Fixed16, Fixed32, None };
inline constexpr EnumNames<FieldType, 6> kFieldTypeNames{{{{FieldType::I16, "i16"},
                                                           {FieldType::I32, "i32"},
                                                           {FieldType::F32, "f32"},
                                                           {FieldType::Fixed16, "fixed16"},
                                                           {FieldType::Fixed32, "fixed32"},
                                                           {FieldType::None, "none"}}}};
inline const char* to_string(FieldType v) { return kFieldTypeNames.name(v); }
/// The types an orientation may have: every field type but "none", the last.
inline constexpr EnumNames<FieldType, 5> kOrientationFieldTypeNames = [] {
  EnumNames<FieldType, 5> names{};
  for (std::size_t k = 0; k < names.entries.size(); ++k) names.entries[k] = kFieldTypeNames.entries[k];
  return names;
}();

enum class Endian { Little, Big };
inline constexpr EnumNames<Endian, 2> kEndianNames{{{{Endian::Little, "little"}, {Endian::Big, "big"}}}};
inline const char* to_string(Endian v) { return kEndianNames.name(v); }

/// How a sensor's orientation is sent: a quaternion, or three Euler (Tait-Bryan) angles.
enum class OrientationKind { Quaternion, Euler };
inline constexpr EnumNames<OrientationKind, 2> kOrientationKindNames{
    {{{OrientationKind::Quaternion, "quaternion"}, {OrientationKind::Euler, "euler"}}}};
inline const char* to_string(OrientationKind v) { return kOrientationKindNames.name(v); }

/// One sensor inside a report; the role it feeds is the key it sits under ([trackers.head], ...).
struct SensorConfig {
  bool enabled = false;
  int station = 0;  ///< value of the station byte that selects this sensor (station mode only)
  int offset = 0;   ///< byte offset of this sensor's block (position, orientation) in the report
  /// With position_type = "none": the position this role reports, in the tracker's axes (before axis_remap), mm.
  std::array<double, 3> fixed_position_mm = {0.0, 0.0, 0.0};
  /// [trackers.stylus] only: the stylus's tip in the sensor's own frame, mm (`lungar calibrate pivot` finds it).
  /// Registration reads the stylus at its tip; all 0: not found yet, which `lungar calibrate` refuses as missing.
  std::array<double, 3> tip_offset_mm = {0.0, 0.0, 0.0};

  bool operator==(const SensorConfig&) const = default;
};

/// [trackers.report]: the byte layout of one HID input report. Offsets are bytes from the start of what
/// hid_read returns (the report id byte included when report_id >= 0); field offsets are relative to the sensor
/// block.
struct ReportConfig {
  int report_id = 1;  ///< first byte of every report; -1: the device does not number its reports
  int length = 32;    ///< bytes per report, the id byte included
  Endian endian = Endian::Little;
  int station_offset = 1;     ///< byte that names the sensor; -1: every sensor at its fixed offset in each report
  int time_offset = 2;        ///< device timestamp; -1: none (arrival time stands in)
  int time_bits = 32;         ///< unsigned 16 or 32 bits, wraps around
  double time_tick_us = 1.0;  ///< microseconds per timestamp tick
  int position_offset = 0;
  FieldType position_type = FieldType::I32;
  int position_frac_bits = 0;                 ///< fixed-point types: fractional bits
  double position_scale = 0.01;               ///< mm per unit (after the fixed-point division)
  std::string position_components = "x,y,z";  ///< what the device sends, in order, with its signs
  OrientationKind orientation = OrientationKind::Quaternion;
  int orientation_offset = 12;
  FieldType orientation_type = FieldType::Fixed16;
  int orientation_frac_bits = 14;
  double orientation_scale = 1.0;                  ///< quaternion units, or degrees for Euler angles, per unit
  std::string orientation_components = "w,x,y,z";  ///< quaternion components or Euler axes, in sent order
  std::string euler_sequence = "zyx";              ///< intrinsic Tait-Bryan order: "zyx" is R = Rz(a) Ry(b) Rx(c)

  bool operator==(const ReportConfig&) const = default;
};

/// What decoding needs of [trackers], whatever the device: the report's layout, the sensor each role reads and the
/// world frame the poses are put in. make_layout() and make_world_frame() read this and nothing else; the
/// [trackers] table (tracker_config.h) derives from it, so its keys stay one flat table in code as in TOML.
struct LayoutConfig {
  double quat_norm_tolerance = 0.05;  ///< a decoded quaternion's |norm - 1| above this is malformed
  std::array<double, 3> workspace_min_mm = {-3000.0, -3000.0, -3000.0};  ///< world frame
  std::array<double, 3> workspace_max_mm = {3000.0, 3000.0, 3000.0};
  std::string axis_remap = "x,y,z";  ///< world axes in terms of the tracker's: "x,-z,y" is world y = -tracker z
  std::array<double, 3> world_offset_mm = {0.0, 0.0, 0.0};  ///< tracker origin in the world, mm
  ReportConfig report;
  SensorConfig head{true, 1, 6, {}};
  SensorConfig patient{true, 2, 6, {}};
  SensorConfig stylus{false, 3, 6, {}};

  bool operator==(const LayoutConfig&) const = default;
};

/// One entry of a component list such as "w,-x,-y,-z": the index of its letter in the alphabet given to
/// parse_signed_axes() and its sign (+1 or -1).
struct SignedAxis {
  int index = 0;
  int sign = 1;
};

/// Parses a comma-separated permutation of `letters` ("x,-z,y" over "xyz"), each letter once, optionally
/// preceded by '-': the syntax of axis_remap and the report's component lists. nullopt when the text is not such
/// a permutation.
inline std::optional<std::vector<SignedAxis>> parse_signed_axes(std::string_view text, std::string_view letters) {
  std::vector<SignedAxis> out;
  std::vector<bool> seen(letters.size(), false);
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    std::string_view item = text.substr(pos, comma - pos);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    SignedAxis a;
    if (!item.empty() && (item.front() == '-' || item.front() == '+')) {
      a.sign = item.front() == '-' ? -1 : 1;
      item.remove_prefix(1);
    }
    if (item.size() != 1) return std::nullopt;
    const std::size_t index = letters.find(item.front());
    if (index == std::string_view::npos || seen[index]) return std::nullopt;
    seen[index] = true;
    a.index = static_cast<int>(index);
    out.push_back(a);
    pos = comma + 1;
  }
  if (out.size() != letters.size()) return std::nullopt;
  return out;
}

}  // namespace lungar::drivers
