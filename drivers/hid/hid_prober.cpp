/// @file hid_prober.cpp
/// @brief Finding the configured tracker among the HID devices hidapi enumerates.
#include <hidapi/hidapi.h>

#include <cwchar>

#include "drivers/hid/hid_interface.h"

namespace lungar::drivers {

namespace {

std::string narrow(const wchar_t* w) {
  std::string out;
  if (!w) return out;
  for (; *w; ++w) out.push_back(*w < 128 ? static_cast<char>(*w) : '?');
  return out;
}

}  // namespace

std::optional<HidFound> hid_probe(const HidConfig& hid) {
  // Strings come from the enumeration: under umockdev (and some kernels) they cannot be read from an open handle.
  hid_device_info* list = hid_enumerate(hid.vendor_id, hid.product_id);
  std::optional<HidFound> found;
  for (hid_device_info* d = list; d && !found; d = d->next) {
    if (!hid.path.empty() && hid.path != d->path) continue;
    if (!hid.serial.empty() && hid.serial != narrow(d->serial_number)) continue;
    found = HidFound{d->path, d->vendor_id, d->product_id, narrow(d->serial_number), narrow(d->product_string),
                     narrow(d->manufacturer_string)};
  }
  hid_free_enumeration(list);
  return found;
}

}  // namespace lungar::drivers
