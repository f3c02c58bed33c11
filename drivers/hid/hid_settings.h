/// @file hid_settings.h
/// @brief [trackers.hid]: the HID driver's settings, beside it; tracker_config.h composes them into [trackers].
/// @ingroup drivers
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lungar::drivers {

/// [trackers.hid]: which USB HID device, and what it is told when opened.
struct HidConfig {
  std::uint16_t vendor_id = 0;   ///< 0: any
  std::uint16_t product_id = 0;  ///< 0: any
  std::string serial;
  std::string path;               ///< hidraw path; wins over ids when set
  double read_timeout_ms = 10.0;  ///< hid_read_timeout's wait, so the thread notices stop and staleness
  /// Feature reports sent in order (hid_send_feature_report) each time the device is opened, report id first:
  /// for trackers that stream nothing until told to. Hex text in TOML ("0x02 0x01").
  std::vector<std::vector<std::uint8_t>> init_feature_reports;

  bool operator==(const HidConfig&) const = default;
};

}  // namespace lungar::drivers
