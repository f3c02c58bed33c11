/// @file hid_open_failure.h
/// @brief Why the configured HID tracker could not be opened, as one log line that names `lungar doctor`'s fix:
///        no device matches the profile, or its hidraw node refuses this user. The reader says each reason once
///        per outage, then retries quietly.
/// @ingroup drivers
#pragma once

#include <string>

#include "drivers/hid/hid_interface.h"

namespace lungar::drivers {

struct HidOpenFailure {
  std::string reason;  ///< tells one reason from another: a new one is said again, the same one is not
  std::string line;    ///< the log line
};

/// No HID device matches `hid` (vendor/product ids, serial, path).
HidOpenFailure hid_no_match(const HidConfig& hid);
/// `found` matches but open() failed with `err` (errno): EACCES or EPERM is the udev rule's to fix.
HidOpenFailure hid_cannot_open(const HidFound& found, int err);

}  // namespace lungar::drivers
