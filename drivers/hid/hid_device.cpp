/// @file hid_device.cpp
/// @brief The HID reader thread: disconnected -> opening -> streaming <-> stale, with back-off on reopen.
#include <hidapi/hidapi.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <thread>

#include "drivers/hid/hid_hotplug.h"
#include "drivers/hid/hid_interface.h"
#include "drivers/hid/hid_open_failure.h"
#include "drivers/tracker/reopen_backoff.h"
#include "drivers/tracker/tracker_core.h"
#include "drivers/tracker/tracker_device.h"

namespace lungar::drivers {

namespace {

class HidDevice final : public TrackerDevice {
 public:
  HidDevice(const HidConfig& s, double reopen_backoff_ms)
      : hid_(s), backoff_(reopen_backoff_ms), read_timeout_ms_(std::max(1, static_cast<int>(s.read_timeout_ms))) {}

  ~HidDevice() override { close(); }

  void run(TrackerCore& core, std::stop_token stop) override {
    if (!hotplug_.start(hid_.vendor_id, hid_.product_id)) {
      core.log(-1, "hid: hot-plug notifications unavailable (%s); re-enumerating with back-off from %lld ms",
               hotplug_.why().c_str(), backoff_.first_ms());
    }
    const auto length = static_cast<std::size_t>(core.layout().length);
    std::array<std::uint8_t, kTrkMaxReport> buf{};
    std::int64_t next_presence_check = 0;
    bool ever_streamed = false;
    core.set_state(TrackerState::Disconnected);
    while (!stop.stop_requested()) {
      const std::int64_t now = monotonic_ns();
      if (!dev_) {
        if (!backoff_.due(now) && !hotplug_.take_event()) {
          std::this_thread::sleep_for(std::chrono::milliseconds(read_timeout_ms_));
          core.tick(monotonic_ns());
          continue;
        }
        core.set_state(TrackerState::Opening);
        if (open(core)) {
          if (ever_streamed) core.count_reconnect();
          ever_streamed = true;
          backoff_.opened();
          core.count_open();  // stays "opening" until the first accepted report
          next_presence_check = monotonic_ns() + backoff_.first_ns();
        } else {
          core.set_state(TrackerState::Disconnected);
          backoff_.failed(monotonic_ns());
        }
        continue;
      }
      // Exactly one report length per read: on a byte-stream node a longer read would merge two reports.
      const int n = hid_read_timeout(dev_, buf.data(), length, read_timeout_ms_);
      const std::int64_t t = monotonic_ns();
      if (n < 0) {
        core.log(-1, "hid: %s lost (read error); reopening", found_.path.c_str());
        lose(core);
        continue;
      }
      if (n > 0) core.feed(std::span<const std::uint8_t>(buf.data(), static_cast<std::size_t>(n)), t);
      core.tick(t);
      // A silent device may have been unplugged without the read failing (some kernels, emulated nodes):
      // when it says nothing, look for it in the enumeration now and then.
      if (core.state() != TrackerState::Streaming && t >= next_presence_check) {
        next_presence_check = t + backoff_.first_ns();
        if (!hid_probe(probe_settings())) {
          core.log(-1, "hid: %s is gone from the bus; reopening", found_.path.c_str());
          lose(core);
        }
      }
    }
    close();
  }

  std::string describe() const override {
    char ids[32];
    std::snprintf(ids, sizeof ids, "%04x:%04x", hid_.vendor_id, hid_.product_id);
    return "hid " + (hid_.path.empty() ? std::string(ids) : hid_.path) +
           (hid_.serial.empty() ? std::string() : " serial " + hid_.serial);
  }
  std::string trk_description() const override {
    // The device is known only once it is opened; the configured match is what a header can say up front.
    char ids[64];
    std::snprintf(ids, sizeof ids, "vendor_id=0x%04x\nproduct_id=0x%04x\n", hid_.vendor_id, hid_.product_id);
    return std::string("source=hid\n") + ids + "serial=" + hid_.serial + "\npath=" + hid_.path + "\n";
  }
  TrkSource trk_source() const override { return TrkSource::Hid; }

 private:
  HidConfig probe_settings() const {
    HidConfig s = hid_;
    s.path = found_.path;  // the very node that was open
    return s;
  }

  bool open(TrackerCore& core) {
    auto found = hid_probe(hid_);
    if (!found) return say_once(core, hid_no_match(hid_));
    dev_ = hid_open_path(found->path.c_str());
    if (!dev_) return say_once(core, hid_cannot_open(*found, open_errno(found->path)));
    said_.clear();  // a later outage says its reason again
    found_ = *found;
    core.log(-1, "hid: opened %s (%04x:%04x %s %s, serial %s)", found_.path.c_str(), found_.vendor_id,
             found_.product_id, found_.manufacturer.c_str(), found_.product.c_str(), found_.serial.c_str());
    return send_init_reports(core);
  }

  /// [trackers.hid] init_feature_reports, in order, on every open: a tracker that streams nothing until told to
  /// forgets it when it is unplugged. A refused report closes the device; the next attempt tries again.
  bool send_init_reports(TrackerCore& core) {
    const auto& reports = hid_.init_feature_reports;
    for (std::size_t k = 0; k < reports.size(); ++k) {
      if (hid_send_feature_report(dev_, reports[k].data(), reports[k].size()) < 0) {
        const wchar_t* why = hid_error(dev_);
        core.log(-1, "hid: trackers.hid.init_feature_reports[%zu] (%zu bytes, report id 0x%02x) was refused by %s: %ls",
                 k, reports[k].size(), reports[k][0], found_.path.c_str(), why ? why : L"unknown error");
        close();
        return false;
      }
    }
    if (!reports.empty()) {
      core.log(-1, "hid: sent %zu init feature report(s) to %s", reports.size(), found_.path.c_str());
    }
    return true;
  }

  /// Logs why the open failed when the reason is new: an absent tracker retried every few seconds says so once,
  /// not on every try. Always false (not opened).
  bool say_once(TrackerCore& core, const HidOpenFailure& failure) {
    if (failure.reason == said_) return false;
    said_ = failure.reason;
    core.log(-1, "%s", failure.line.c_str());
    return false;
  }

  /// What open() says of `path` as hidapi opens it (hidapi keeps no errno): EACCES for a node this user may not
  /// read.
  static int open_errno(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
      ::close(fd);
      return EIO;  // it opens now: whatever hidapi met was passing
    }
    return errno;
  }

  void lose(TrackerCore& core) {
    close();
    core.set_state(TrackerState::Disconnected);
    backoff_.lost(monotonic_ns());
  }

  void close() {
    if (dev_) hid_close(dev_);
    dev_ = nullptr;
  }

  HidConfig hid_;
  ReopenBackoff backoff_;
  int read_timeout_ms_;
  hid_device* dev_ = nullptr;
  HidFound found_;
  std::string said_;  ///< the reason of the open failure last logged ("": none since the last open)
  UsbHotplug hotplug_;
};

}  // namespace

std::unique_ptr<TrackerDevice> hid_create(const HidConfig& settings, double reopen_backoff_ms) {
  return std::make_unique<HidDevice>(settings, reopen_backoff_ms);
}

}  // namespace lungar::drivers
