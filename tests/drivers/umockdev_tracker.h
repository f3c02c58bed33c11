/// @file umockdev_tracker.h
/// @brief Test helper: an emulated hidraw tracker (umockdev) that real hidapi opens, and that a test writes
/// raw reports into, unplugs and plugs back; it answers the hidraw ioctls and records the feature reports sent.
/// The test binary must run under umockdev-wrapper (lungar_test_suite(... WRAPPER umockdev-wrapper)). Recipe:
/// ../shared/notes/umockdev-hidraw.md.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace lungar::testing {

struct UmockdevTrackerSpec {
  std::uint16_t vendor_id = 0x1234;
  std::uint16_t product_id = 0x5678;
  std::string serial = "SN0001";
  std::string product = "Pose Tracker";
  int report_id = 1;    ///< -1: unnumbered reports
  int length = 32;      ///< bytes per report, the id byte included (as in config [trackers.report])
  int hidraw_index = 0; ///< the node is /dev/hidraw<index>
  bool refuse_feature_reports = false;  ///< HIDIOCSFEATURE fails (EPIPE, a stalled control transfer)
};

class UmockdevTracker {
 public:
  UmockdevTracker();
  ~UmockdevTracker();
  UmockdevTracker(const UmockdevTracker&) = delete;
  UmockdevTracker& operator=(const UmockdevTracker&) = delete;

  /// True when the process runs under umockdev-wrapper (otherwise nothing here can work; tests skip).
  static bool available();

  /// Plugs the device in (again, after unplug()). umockdev cannot create a node name twice in one testbed,
  /// so a replug takes the next free hidraw index, as the kernel often does; dev_path() says which.
  /// False with error() on failure.
  bool plug(const UmockdevTrackerSpec& spec);
  /// Removes the device from the emulated bus, as pulling the cable would.
  void unplug();
  /// Writes one raw report as the device would send it. False when the device is not plugged in.
  /// The node is a pseudo-terminal: keep less than 4 KiB unread (its line discipline's buffer), i.e. write at
  /// the device's pace or wait for the reader, or a report will be split across two reads.
  bool write(std::span<const std::uint8_t> report);

  std::string dev_path() const;  ///< /dev/hidrawN
  const std::string& error() const { return error_; }
  /// Every feature report the host sent (HIDIOCSFEATURE), in order, over all plugs: what the device received.
  std::vector<std::vector<std::uint8_t>> feature_reports() const;

  struct Impl;  ///< the testbed; named here so that the .cpp's ioctl handler can reach it

 private:
  std::unique_ptr<Impl> impl_;
  std::string error_;
};

/// The HID report descriptor of a vendor-page device with one input report of `length` bytes (id included).
std::string vendor_report_descriptor_hex(int report_id, int length);

}  // namespace lungar::testing
