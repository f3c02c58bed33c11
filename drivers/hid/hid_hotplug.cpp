/// @file hid_hotplug.cpp
/// @brief libusb_hotplug_register_callback and an event thread; every failure becomes "unavailable".
#include "drivers/hid/hid_hotplug.h"

#include <libusb.h>

namespace lungar::drivers {

int LIBUSB_CALL UsbHotplug::callback(libusb_context*, libusb_device*, libusb_hotplug_event, void* self) {
  static_cast<UsbHotplug*>(self)->event_.store(true, std::memory_order_release);
  return 0;  // stay registered
}

bool UsbHotplug::start(std::uint16_t vendor_id, std::uint16_t product_id) {
  if (libusb_init(&ctx_) != 0) {
    ctx_ = nullptr;
    why_ = "libusb_init failed";
    return false;
  }
  if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
    why_ = "libusb has no hot-plug support here";
    return false;
  }
  const int rc = libusb_hotplug_register_callback(
      ctx_, static_cast<libusb_hotplug_event>(LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED | LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT),
      LIBUSB_HOTPLUG_NO_FLAGS, vendor_id ? vendor_id : LIBUSB_HOTPLUG_MATCH_ANY,
      product_id ? product_id : LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY, &UsbHotplug::callback, this,
      &handle_);
  if (rc != LIBUSB_SUCCESS) {
    why_ = std::string("libusb_hotplug_register_callback: ") + libusb_error_name(rc);
    return false;
  }
  thread_ = std::jthread([this](std::stop_token stop) {
    while (!stop.stop_requested()) {
      timeval tv{0, 100'000};
      libusb_handle_events_timeout_completed(ctx_, &tv, nullptr);
    }
  });
  return true;
}

UsbHotplug::~UsbHotplug() {
  if (thread_.joinable()) {
    thread_.request_stop();
    libusb_hotplug_deregister_callback(ctx_, handle_);  // also wakes the event loop
    thread_.join();
  }
  if (ctx_) libusb_exit(ctx_);
}

}  // namespace lungar::drivers
