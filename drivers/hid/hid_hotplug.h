/// @file hid_hotplug.h
/// @brief libusb hot-plug notifications for the tracker's vendor/product ids, where the platform has them.
/// @ingroup drivers
///
/// The HID thread re-enumerates on a back-off timer anyway; an arrival event only makes it look at once.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include <libusb.h>

namespace lungar::drivers {

class UsbHotplug {
 public:
  UsbHotplug() = default;
  ~UsbHotplug();
  UsbHotplug(const UsbHotplug&) = delete;
  UsbHotplug& operator=(const UsbHotplug&) = delete;

  /// Registers for arrivals and departures of vendor:product (0 = any) and starts the event thread. False
  /// with why() when libusb or its hot-plug capability is unavailable (no usbfs, containers, tests).
  bool start(std::uint16_t vendor_id, std::uint16_t product_id);
  /// True once per batch of events since the last call.
  bool take_event() { return event_.exchange(false, std::memory_order_acq_rel); }
  const std::string& why() const { return why_; }

 private:
  static int LIBUSB_CALL callback(libusb_context* ctx, libusb_device* dev, libusb_hotplug_event event, void* self);
  libusb_context* ctx_ = nullptr;
  int handle_ = 0;
  std::jthread thread_;
  std::atomic<bool> event_{false};
  std::string why_;
};

}  // namespace lungar::drivers
