/// @file tracker_check.cpp
/// @brief The tracker check: for HID, the configured device's hidraw node is there and this user can open it as
/// hidapi does (read and write); when it cannot, the fix is the udev rule (the exact command) or a new session.
/// For OpenIGTLink, the server accepts a connection.
#include <fcntl.h>
#include <pwd.h>
#include <unistd.h>

#include <hidapi/hidapi.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "drivers/hid/hid_interface.h"
#include "drivers/igtl/tcp_socket.h"
#include "drivers/tracker/tracker_config.h"
#include "drivers/trk/trk_reader.h"
#include "platform/doctor/checks.h"

namespace lungar::platform::doctor {

namespace {

std::string hex4(unsigned v) {
  char b[8];
  std::snprintf(b, sizeof b, "%04x", v & 0xFFFFu);
  return b;
}

std::string user_name() {
  const passwd* pw = ::getpwuid(::geteuid());
  return pw != nullptr ? pw->pw_name : "uid " + std::to_string(::geteuid());
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// The first rules file in `dirs` with an active line naming both ids; "" when none does.
std::string find_udev_rule(const std::vector<std::string>& dirs, const std::string& vid, const std::string& pid) {
  for (const auto& dir : dirs) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      if (entry.path().extension() != ".rules") continue;
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);) {
        line = lower(line);
        if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        if (line.find("idvendor}==\"" + vid + "\"") != std::string::npos &&
            line.find("idproduct}==\"" + pid + "\"") != std::string::npos) {
          return entry.path().string();
        }
      }
    }
  }
  return "";
}

/// The command that gives the seated user the tracker (as scripts/99-lungar.rules does for the test tracker).
std::string udev_rule_command(const std::string& vid, const std::string& pid) {
  const std::string ids = "ATTRS{idVendor}==\"" + vid + "\", ATTRS{idProduct}==\"" + pid + "\"";
  const std::string usb_ids = "ATTR{idVendor}==\"" + vid + "\", ATTR{idProduct}==\"" + pid + "\"";
  const std::string grant = ", TAG+=\"uaccess\", RUN{builtin}+=\"uaccess\"";
  return "printf '%s\\n' 'KERNEL==\"hidraw*\", SUBSYSTEM==\"hidraw\", " + ids + grant +
         "' 'SUBSYSTEM==\"usb\", ENV{DEVTYPE}==\"usb_device\", " + usb_ids + grant +
         "' | sudo tee /etc/udev/rules.d/70-lungar-" + vid + "-" + pid +
         ".rules && sudo udevadm control --reload-rules && sudo udevadm trigger";
}

Check hid_node_check(const drivers::HidConfig& hid, const DoctorEnv& env) {
  hid_init();
  const std::string wanted = !hid.path.empty() ? hid.path
                                               : (hid.vendor_id == 0 && hid.product_id == 0
                                                      ? std::string("any HID device")
                                                      : hex4(hid.vendor_id) + ":" + hex4(hid.product_id));
  const auto found = drivers::hid_probe(hid);
  if (!found) {
    return failed("tracker", "no HID tracker " + wanted + " (trackers.hid) is plugged in",
                  "plug the tracker in and check that `lsusb` lists it; if its ids differ, set trackers.hid.vendor_id "
                  "and product_id (or trackers.hid.path) in the config");
  }
  const std::string vid = hex4(found->vendor_id), pid = hex4(found->product_id);
  const std::string what = found->path + " (" + vid + ":" + pid + " " + found->manufacturer + " " + found->product +
                           (found->serial.empty() ? "" : ", " + found->serial) + ")";
  const std::string rule = find_udev_rule(env.udev_rule_dirs, vid, pid);
  const int fd = ::open(found->path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);  // as hidapi opens it
  if (fd < 0) {
    const int err = errno;
    const std::string detail = what + " cannot be opened by user " + user_name() + ": " + std::strerror(err);
    if (err != EACCES && err != EPERM) return failed("tracker", detail, "replug the tracker; check `dmesg` for it");
    if (rule.empty()) return failed("tracker", detail + "; no udev rule grants it", udev_rule_command(vid, pid));
    return failed("tracker", detail + "; " + rule + " grants it to the user seated at the machine",
                  "log in on the machine's own screen (not over ssh), then replug the tracker or run sudo udevadm "
                  "trigger");
  }
  ::close(fd);
  if (::geteuid() == 0 && rule.empty()) {
    return warned("tracker", what + " readable, but only because this runs as root: no udev rule grants it",
                  "for the trainer's account: " + udev_rule_command(vid, pid));
  }
  return passed("tracker", what + " readable by user " + user_name() + (rule.empty() ? "" : " (" + rule + ")"));
}

/// The OpenIGTLink server answers on host:port (what lungar connects to; the messages come once it streams).
Check igtl_server_check(const drivers::IgtlConfig& g) {
  const std::string where = g.host + ":" + std::to_string(g.port);
  if (auto s = drivers::TcpSocket::connect(g.host, g.port, static_cast<int>(g.connect_timeout_ms)); !s) {
    return failed("tracker", "OpenIGTLink: " + s.error() + " (trackers.igtl)",
                  "start PlusServer (its PlusOpenIGTLinkServer ListeningPort) or a Slicer OpenIGTLinkIF connector in "
                  "server mode on " +
                      where + ", or set trackers.igtl.host and port (or --tracker igtl:HOST:PORT)");
  }
  return passed("tracker", "OpenIGTLink server " + where + " accepts connections (head '" + g.head + "', patient '" +
                               g.patient + "', stylus '" + g.stylus + "')");
}

}  // namespace

Check check_tracker(const drivers::TrackerConfig& t, const DoctorEnv& env) {
  switch (t.source) {
    case drivers::TrackerSource::Mock:
      return passed("tracker", "mock (" + t.mock.trajectory + "): no device needed");
    case drivers::TrackerSource::Replay: {
      const auto log = drivers::load_trk(t.replay_file);
      if (!log) {
        return failed("tracker", "trackers.replay_file: " + log.error(),
                      "point trackers.replay_file at a .trk log (`lungar-trk info FILE` checks one)");
      }
      if (log->truncated_tail && !t.replay_truncated) {
        return failed("tracker", t.replay_file + ": the log is truncated (its last record stops partway)",
                      "record it again, or replay what it holds with --replay-truncated");
      }
      return passed("tracker", "replay of " + t.replay_file + " (" + std::to_string(log->records.size()) + " reports" +
                                   (log->truncated_tail ? ", truncated" : "") + ")");
    }
    case drivers::TrackerSource::Hid:
      return hid_node_check(t.hid, env);
    case drivers::TrackerSource::Igtl:
      return igtl_server_check(t.igtl);
  }
  return failed("tracker", "trackers.source: unknown", "set trackers.source to mock, hid, igtl or replay");
}

}  // namespace lungar::platform::doctor
