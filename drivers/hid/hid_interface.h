/// @file hid_interface.h
/// @brief The USB HID tracker (hidapi, hidraw backend): finds the device from config, reads one report length
/// at a time, survives unplug and replug (libusb hot-plug, else periodic re-enumeration).
/// @ingroup drivers
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "drivers/hid/hid_settings.h"
#include "drivers/tracker/tracker_device.h"

namespace lungar::drivers {

/// What the prober found.
struct HidFound {
  std::string path;  ///< e.g. /dev/hidraw0
  std::uint16_t vendor_id = 0, product_id = 0;
  std::string serial, product, manufacturer;
};

/// The first HID device matching the settings (path wins; else vendor/product ids, 0 = any, and serial, "" =
/// any), from hid_enumerate(); nullopt when none is plugged in. Call hid_init() first (make_tracker does).
std::optional<HidFound> hid_probe(const HidConfig& hid);

/// A source for the configured device. It never fails to start: an absent device is "disconnected".
std::unique_ptr<TrackerDevice> hid_create(const HidConfig& settings, double reopen_backoff_ms);

}  // namespace lungar::drivers
