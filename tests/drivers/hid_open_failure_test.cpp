// Why a HID tracker cannot be opened, in the words the log gives once: the profile that matched nothing, or the
// node this user may not read, each with `lungar doctor`'s fix.
#include <gtest/gtest.h>

#include <cerrno>

#include "drivers/hid/hid_open_failure.h"

using namespace lungar::drivers;

TEST(HidOpenFailure, APermissionDeniedNodeNamesTheUdevRuleFromDoctor) {
  const HidFound found{"/dev/hidraw3", 0x1234, 0x5678, "SN0001", "Pose Tracker", "FakeVendor"};
  const HidOpenFailure f = hid_cannot_open(found, EACCES);
  EXPECT_NE(f.line.find("cannot open /dev/hidraw3 (1234:5678): Permission denied"), std::string::npos) << f.line;
  EXPECT_NE(f.line.find("this user may not read it"), std::string::npos) << f.line;
  EXPECT_NE(f.line.find("lungar doctor"), std::string::npos) << f.line;
  EXPECT_NE(f.line.find("udev rule"), std::string::npos) << f.line;
  EXPECT_EQ(hid_cannot_open(found, EPERM).reason, f.reason) << "one reason, said once";
  EXPECT_NE(hid_cannot_open(found, ENODEV).reason, f.reason) << "another reason is said again";
  EXPECT_EQ(hid_cannot_open(found, ENODEV).line.find("udev rule"), std::string::npos);
}

TEST(HidOpenFailure, NoMatchNamesTheProfileItLookedFor) {
  HidConfig hid;
  EXPECT_NE(hid_no_match(hid).line.find("any vendor and product"), std::string::npos);
  hid.vendor_id = 0x1234;
  hid.product_id = 0x5678;
  hid.serial = "SN7";
  const HidOpenFailure f = hid_no_match(hid);
  EXPECT_NE(f.line.find("trackers.hid: vendor_id 0x1234, product_id 0x5678, serial SN7"), std::string::npos) << f.line;
  EXPECT_NE(f.line.find("lungar doctor"), std::string::npos) << f.line;
  EXPECT_NE(f.reason, hid_cannot_open(HidFound{"/dev/hidraw0", 0x1234, 0x5678, "", "", ""}, EACCES).reason);
}
