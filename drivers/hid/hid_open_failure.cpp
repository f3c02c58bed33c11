/// @file hid_open_failure.cpp
/// @brief The reasons' words.
#include "drivers/hid/hid_open_failure.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace lungar::drivers {

namespace {

/// Doctor checks what the run's own options would open, so the user is told to give it the same ones.
constexpr const char* kDoctor = "`lungar doctor` (with this run's --config/--tracker options)";

std::string profile_of(const HidConfig& hid) {
  char ids[48];
  if (hid.vendor_id == 0 && hid.product_id == 0) {
    std::snprintf(ids, sizeof ids, "any vendor and product");
  } else {
    std::snprintf(ids, sizeof ids, "vendor_id 0x%04x, product_id 0x%04x", hid.vendor_id, hid.product_id);
  }
  std::string out = ids;
  if (!hid.serial.empty()) out += ", serial " + hid.serial;
  if (!hid.path.empty()) out += ", path " + hid.path;
  return out;
}

}  // namespace

HidOpenFailure hid_no_match(const HidConfig& hid) {
  return {"no-match", "hid: no HID device matches the profile (trackers.hid: " + profile_of(hid) +
                          "); plug the tracker in, or fix the ids: " + kDoctor +
                          " says which; retrying quietly until it appears"};
}

HidOpenFailure hid_cannot_open(const HidFound& found, int err) {
  char ids[16];
  std::snprintf(ids, sizeof ids, "%04x:%04x", found.vendor_id, found.product_id);
  const std::string what = "hid: cannot open " + found.path + " (" + ids + "): " + std::strerror(err);
  if (err == EACCES || err == EPERM) {
    return {"permission " + found.path,
            what + ": this user may not read it; " + kDoctor + " gives the udev rule that grants it; retrying quietly"};
  }
  return {"open " + found.path + " " + std::to_string(err),
          what + "; replug the tracker, and " + kDoctor + " checks it; retrying quietly"};
}

}  // namespace lungar::drivers
