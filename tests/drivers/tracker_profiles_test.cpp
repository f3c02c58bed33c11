// The shipped device profiles (config/trackers/): each one loads, and reports built byte by byte the way that
// device sends them (the facts its file cites from Monado's or OpenHMD's driver) decode through it to the pose
// that was put in.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/decode/decoder.h"

using namespace lungar;
using namespace lungar::drivers;

namespace {

struct Profile {
  TrackerConfig settings;
  ReportLayout layout;
};

/// The shipped profile `name`, checked to be a HID tracker with the USB ids its driver gives.
Profile profile(const std::string& name, std::uint16_t vendor_id, std::uint16_t product_id) {
  auto r = drivers::tracker_config_from_file(std::string(LUNGAR_SOURCE_DIR) + "/config/trackers/" + name);
  EXPECT_TRUE(r) << r.error();
  Profile p;
  if (r) p.settings = *r;
  EXPECT_EQ(p.settings.source, TrackerSource::Hid);
  EXPECT_EQ(p.settings.hid.vendor_id, vendor_id);
  EXPECT_EQ(p.settings.hid.product_id, product_id);
  auto l = make_layout(p.settings);
  EXPECT_TRUE(l) << l.error();
  p.layout = l ? *l : ReportLayout{};
  return p;
}

void put_i16(std::vector<std::uint8_t>& b, std::size_t at, double v) {  // little-endian int16
  const auto u = static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(v)));
  b[at] = static_cast<std::uint8_t>(u);
  b[at + 1] = static_cast<std::uint8_t>(u >> 8);
}

void put_f32(std::vector<std::uint8_t>& b, std::size_t at, double v) {  // little-endian float32
  const auto u = std::bit_cast<std::uint32_t>(static_cast<float>(v));
  for (int k = 0; k < 4; ++k) b[at + k] = static_cast<std::uint8_t>(u >> (8 * k));
}

/// Orientations to send: none has a zero component, so a lost sign or a swapped pair shows.
std::vector<Eigen::Quaterniond> orientations() {
  std::vector<Eigen::Quaterniond> out;
  for (double a = -2.5; a < 3.0; a += 0.9) {
    out.push_back(Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d(0.3, -0.8, 0.5).normalized())) *
                  Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX())));
  }
  return out;
}

void expect_head(const DecodedReport& d, const Eigen::Quaterniond& q, const Profile& p, double tol) {
  ASSERT_EQ(d.error, DecodeError::None) << to_string(d.error);
  ASSERT_EQ(d.count, 1);
  EXPECT_EQ(d.poses[0].role, Role::Head);
  EXPECT_LT(d.poses[0].orientation().angularDistance(q), tol);
  EXPECT_EQ(d.poses[0].position_mm, p.settings.head.fixed_position_mm);  // orientation only: where it is worn
  EXPECT_FALSE(d.has_time);
}

}  // namespace

// Monado src/xrt/drivers/hdk/hdk_device.cpp: 32-byte version 3 reports, no id; version and sequence bytes, then
// Q1.14 little-endian int16 sent as x, -z, y, w.
TEST(TrackerProfiles, OsvrHdk) {
  const Profile p = profile("osvr-hdk.toml", 0x1532, 0x0b00);
  std::uint8_t sequence = 0;
  for (const Eigen::Quaterniond& q : orientations()) {
    std::vector<std::uint8_t> r(32, 0);
    r[0] = 0x13;  // report version 3, HDMI status 1
    r[1] = sequence++;
    put_i16(r, 2, q.x() * 16384);
    put_i16(r, 4, -q.z() * 16384);
    put_i16(r, 6, q.y() * 16384);
    put_i16(r, 8, q.w() * 16384);
    put_i16(r, 10, 1234);  // angular velocity: not read
    expect_head(decode_report(r, p.layout), q, p, 2e-4);
  }
  EXPECT_EQ(decode_report(std::vector<std::uint8_t>(16, 0), p.layout).error, DecodeError::WrongLength);  // version 1
}

// OpenHMD src/drv_3glasses/: 64-byte reports with id 0x83; status, a 16-bit timestamp, temperature, IPD, padding,
// then float32 x, y, z, w at byte 8.
TEST(TrackerProfiles, ThreeGlassesD3) {
  const Profile p = profile("3glasses-d3.toml", 0x2b1c, 0x0201);
  std::uint16_t stamp = 65000;
  for (const Eigen::Quaterniond& q : orientations()) {
    std::vector<std::uint8_t> r(64, 0);
    r[0] = 0x83;
    r[1] = 2;  // panel running
    r[2] = static_cast<std::uint8_t>(stamp);
    r[3] = static_cast<std::uint8_t>(stamp >> 8);
    stamp += 1000;
    r[4] = 36;  // temperature
    r[5] = 64;  // IPD
    put_f32(r, 8, q.x());
    put_f32(r, 12, q.y());
    put_f32(r, 16, q.z());
    put_f32(r, 20, q.w());
    put_f32(r, 24, 9.81);  // accelerometer: not read
    expect_head(decode_report(r, p.layout), q, p, 1e-6);
  }
  std::vector<std::uint8_t> version(64, 0);
  version[0] = 0x06;  // the firmware-version feature report's id
  EXPECT_EQ(decode_report(version, p.layout).error, DecodeError::UnknownReportId);
}

// OpenHMD src/drv_sparkfun_9dof/sparkFun9DoF.c: 16-byte reports, no id, float32 w, x, y, z.
TEST(TrackerProfiles, SparkFun9DofRazor) {
  const Profile p = profile("sparkfun-9dof-razor.toml", 0x1b4f, 0x8d21);
  for (const Eigen::Quaterniond& q : orientations()) {
    std::vector<std::uint8_t> r(16, 0);
    put_f32(r, 0, q.w());
    put_f32(r, 4, q.x());
    put_f32(r, 8, q.y());
    put_f32(r, 12, q.z());
    expect_head(decode_report(r, p.layout), q, p, 1e-6);
  }
}

// Every shipped profile loads and cites the driver file it took its facts from.
TEST(TrackerProfiles, EveryShippedProfileLoadsAndCitesItsDriver) {
  const std::filesystem::path dir = std::filesystem::path(LUNGAR_SOURCE_DIR) / "config" / "trackers";
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().string());
    auto r = drivers::tracker_config_from_file(entry.path().string());
    ASSERT_TRUE(r) << r.error();
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const bool cites = text.find("src/") != std::string::npos &&
                       (text.find("Monado") != std::string::npos || text.find("OpenHMD") != std::string::npos);
    EXPECT_TRUE(cites) << "no open-source driver file cited";
    ++n;
  }
  EXPECT_GE(n, 3);
}
