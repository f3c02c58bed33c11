/// @file umockdev_tracker.cpp
/// @brief The umockdev testbed behind UmockdevTracker: sysfs description, an ioctl handler, the dev fd.
#include "umockdev_tracker.h"

#include <linux/hidraw.h>
#include <sys/ioctl.h>
#include <umockdev.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <vector>

namespace lungar::testing {

struct UmockdevTracker::Impl {
  UMockdevTestbed* testbed = nullptr;
  UmockdevTrackerSpec spec;
  bool plugged = false;
  std::set<int> used;  // node indices this testbed has created (umockdev cannot create one twice)
  // Written by umockdev's worker thread (the ioctl handler), read by the test.
  mutable std::mutex mutex;
  std::vector<std::vector<std::uint8_t>> feature_reports;
};

namespace {

std::string hex2(unsigned v) {
  char b[3];
  std::snprintf(b, sizeof b, "%02X", v & 0xFFu);
  return b;
}

std::string sys_base(const UmockdevTrackerSpec& s) {
  char hid[64];
  std::snprintf(hid, sizeof hid, "0003:%04X:%04X.%04X", s.vendor_id, s.product_id, s.hidraw_index + 1);
  return "/devices/pci0000:00/0000:00:14.0/usb1/1-" + std::to_string(s.hidraw_index + 1) + "/1-" +
         std::to_string(s.hidraw_index + 1) + ":1.0/" + hid;
}

std::vector<std::uint8_t> from_hex(const std::string& hex) {
  std::vector<std::uint8_t> out;
  for (std::size_t k = 0; k + 1 < hex.size(); k += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoi(hex.substr(k, 2), nullptr, 16)));
  }
  return out;
}

/// Answers hidraw's ioctls as the kernel would for this device (umockdev's worker thread calls it): the report
/// descriptor's size and bytes, the raw info, and feature reports, which it records.
gboolean handle_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  auto* impl = static_cast<UmockdevTracker::Impl*>(self);
  const gulong request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const std::vector<std::uint8_t> desc =
      from_hex(vendor_report_descriptor_hex(impl->spec.report_id, impl->spec.length));
  auto reply = [&](const void* data, std::size_t n) -> gboolean {
    UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, n, nullptr);
    if (!d) return FALSE;
    std::memcpy(d->data, data, n);
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
  };
  if (request == HIDIOCGRDESCSIZE) {
    const int size = static_cast<int>(desc.size());
    return reply(&size, sizeof size);
  }
  if (request == HIDIOCGRDESC) {
    hidraw_report_descriptor d{};
    d.size = static_cast<std::uint32_t>(desc.size());
    std::memcpy(d.value, desc.data(), desc.size());
    return reply(&d, sizeof d);
  }
  if (request == HIDIOCGRAWINFO) {
    hidraw_devinfo info{3, static_cast<std::int16_t>(impl->spec.vendor_id),
                        static_cast<std::int16_t>(impl->spec.product_id)};
    return reply(&info, sizeof info);
  }
  if (_IOC_TYPE(request) == 'H' && _IOC_NR(request) == _IOC_NR(HIDIOCSFEATURE(0))) {
    const std::size_t n = _IOC_SIZE(request);
    UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, n, nullptr);
    if (!d) return FALSE;
    {
      std::lock_guard lock(impl->mutex);
      impl->feature_reports.emplace_back(d->data, d->data + n);
    }
    if (impl->spec.refuse_feature_reports) {
      umockdev_ioctl_client_complete(client, -1, EPIPE);
    } else {
      umockdev_ioctl_client_complete(client, static_cast<glong>(n), 0);
    }
    return TRUE;
  }
  return FALSE;  // anything else: ENOTTY, as for an ioctl the device does not know
}

}  // namespace

std::vector<std::vector<std::uint8_t>> UmockdevTracker::feature_reports() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->feature_reports;
}

std::string vendor_report_descriptor_hex(int report_id, int length) {
  const int count = report_id >= 0 ? length - 1 : length;
  std::string d = "0600FF0901A101";           // usage page vendor 0xFF00, usage 1, application collection
  if (report_id >= 0) d += "85" + hex2(static_cast<unsigned>(report_id));
  d += "0902150026FF007508";                  // usage 2, logical 0..255, 8-bit fields
  d += count <= 255 ? "95" + hex2(static_cast<unsigned>(count))
                    : "96" + hex2(static_cast<unsigned>(count)) + hex2(static_cast<unsigned>(count) >> 8);
  d += "8102C0";                              // input (data, variable, absolute), end collection
  return d;
}

UmockdevTracker::UmockdevTracker() : impl_(std::make_unique<Impl>()) {}

UmockdevTracker::~UmockdevTracker() {
  if (impl_->testbed) g_object_unref(impl_->testbed);
}

bool UmockdevTracker::available() {
  // umockdev_in_mock_environment() is meaningful only after a testbed exists (see the recipe).
  return std::getenv("LD_PRELOAD") && std::string(std::getenv("LD_PRELOAD")).find("umockdev") != std::string::npos;
}

std::string UmockdevTracker::dev_path() const { return "/dev/hidraw" + std::to_string(impl_->spec.hidraw_index); }

bool UmockdevTracker::plug(const UmockdevTrackerSpec& spec) {
  if (!impl_->testbed) impl_->testbed = umockdev_testbed_new();
  if (impl_->plugged) unplug();
  UmockdevTrackerSpec s = spec;
  while (impl_->used.count(s.hidraw_index)) ++s.hidraw_index;
  impl_->used.insert(s.hidraw_index);
  impl_->spec = s;
  const std::string node = "hidraw" + std::to_string(s.hidraw_index);
  const std::string base = sys_base(s);
  const std::string usb = base.substr(0, base.rfind('/'));   // the interface
  const std::string usbdev = usb.substr(0, usb.rfind('/'));  // the device
  char ids[128];
  std::snprintf(ids, sizeof ids, "E: HID_ID=0003:%08X:%08X\n", s.vendor_id, s.product_id);
  char usbids[128];
  std::snprintf(usbids, sizeof usbids, "A: idVendor=%04x\\n\nA: idProduct=%04x\\n\n", s.vendor_id, s.product_id);
  const std::string hid_name = base.substr(base.rfind('/') + 1);
  const std::string desc =
      "P: " + base + "/hidraw/" + node + "\nN: " + node + "\nE: DEVNAME=/dev/" + node +
      "\nE: SUBSYSTEM=hidraw\nA: dev=240:" + std::to_string(s.hidraw_index) + "\\n\nL: device=../../../" + hid_name +
      "\n\n"
      "P: " + base + "\n" + ids + "E: HID_NAME=FakeVendor " + s.product +
      "\nE: SUBSYSTEM=hid\nH: report_descriptor=" + vendor_report_descriptor_hex(s.report_id, s.length) + "\n\n"
      "P: " + usb + "\nE: DEVTYPE=usb_interface\nE: SUBSYSTEM=usb\nA: bInterfaceNumber=00\\n\n\n"
      "P: " + usbdev + "\nE: DEVTYPE=usb_device\nE: SUBSYSTEM=usb\n" + usbids +
      "A: bcdDevice=0100\\n\nA: manufacturer=FakeVendor\\n\nA: product=" + s.product + "\\n\nA: serial=" + s.serial +
      "\\n\n";
  GError* err = nullptr;
  if (!umockdev_testbed_add_from_string(impl_->testbed, desc.c_str(), &err)) {
    error_ = std::string("umockdev_testbed_add_from_string: ") + (err ? err->message : "failed");
    if (err) g_error_free(err);
    return false;
  }
  // hid_open_path() asks the node for the descriptor size, the tracker may be sent feature reports: a handler
  // answers (and records) the ioctls.
  UMockdevIoctlBase* handler = UMOCKDEV_IOCTL_BASE(g_object_new(UMOCKDEV_TYPE_IOCTL_BASE, nullptr));
  g_signal_connect(handler, "handle-ioctl", G_CALLBACK(handle_ioctl), impl_.get());
  const bool attached = umockdev_testbed_attach_ioctl(impl_->testbed, ("/dev/" + node).c_str(), handler, &err);
  g_object_unref(handler);
  if (!attached) {
    error_ = std::string("umockdev_testbed_attach_ioctl: ") + (err ? err->message : "failed");
    if (err) g_error_free(err);
    return false;
  }
  // Only now does the device show in hidapi's enumeration (it lists no hid device without HID_UNIQ): a tracker
  // polling for it never opens the node before the handler answers, which hidapi 0.13.1 would take for "not a
  // hidraw device" (and leak its error string).
  umockdev_testbed_set_property(impl_->testbed, ("/sys" + base).c_str(), "HID_UNIQ", s.serial.c_str());
  impl_->plugged = true;
  return true;
}

void UmockdevTracker::unplug() {
  if (!impl_->plugged) return;
  const UmockdevTrackerSpec& s = impl_->spec;
  const std::string base = sys_base(s);
  const std::string usb = base.substr(0, base.rfind('/'));
  umockdev_testbed_remove_device(impl_->testbed, ("/sys" + base + "/hidraw/hidraw" + std::to_string(s.hidraw_index)).c_str());
  umockdev_testbed_remove_device(impl_->testbed, ("/sys" + base).c_str());
  umockdev_testbed_remove_device(impl_->testbed, ("/sys" + usb).c_str());
  umockdev_testbed_remove_device(impl_->testbed, ("/sys" + usb.substr(0, usb.rfind('/'))).c_str());
  impl_->plugged = false;
}

bool UmockdevTracker::write(std::span<const std::uint8_t> report) {
  if (!impl_->plugged) return false;
  const int fd = umockdev_testbed_get_dev_fd(impl_->testbed, dev_path().c_str());
  if (fd < 0) return false;
  std::size_t done = 0;
  while (done < report.size()) {
    const ssize_t w = ::write(fd, report.data() + done, report.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace lungar::testing
