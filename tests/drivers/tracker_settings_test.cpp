// Tests of the [trackers...] schema: the report layout, sensors and validation keys, and their exact errors.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/tracker/tracker_config_toml.h"

using lungar::drivers::tracker_config_from_file;
using lungar::drivers::tracker_config_from_toml;
using lungar::drivers::Endian;
using lungar::drivers::FieldType;
using lungar::drivers::OrientationKind;
using lungar::drivers::parse_signed_axes;

namespace {

std::string error_of(const std::string& toml) {
  auto r = tracker_config_from_toml(toml, "bad.toml");
  EXPECT_FALSE(r) << "expected an error for:\n" << toml;
  return r.error();
}

}  // namespace

TEST(Trackers, ShippedProfileMatchesBuiltInLayout) {
  auto r = tracker_config_from_file(std::string(LUNGAR_SOURCE_DIR) + "/config/default.toml");
  ASSERT_TRUE(r) << r.error();
  const auto& t = *r;
  const lungar::drivers::TrackerConfig d;
  EXPECT_EQ(t.report.report_id, d.report.report_id);
  EXPECT_EQ(t.report.length, d.report.length);
  EXPECT_EQ(t.report.station_offset, d.report.station_offset);
  EXPECT_EQ(t.report.time_offset, d.report.time_offset);
  EXPECT_EQ(t.report.position_type, d.report.position_type);
  EXPECT_DOUBLE_EQ(t.report.position_scale, d.report.position_scale);
  EXPECT_EQ(t.report.orientation_type, d.report.orientation_type);
  EXPECT_EQ(t.report.orientation_frac_bits, d.report.orientation_frac_bits);
  EXPECT_EQ(t.report.orientation_components, d.report.orientation_components);
  EXPECT_EQ(t.head.station, d.head.station);
  EXPECT_EQ(t.patient.offset, d.patient.offset);
  EXPECT_EQ(t.stylus.enabled, d.stylus.enabled);
  EXPECT_EQ(t.workspace_max_mm, d.workspace_max_mm);
  EXPECT_DOUBLE_EQ(t.quat_norm_tolerance, d.quat_norm_tolerance);
  EXPECT_EQ(t.axis_remap, d.axis_remap);
}

TEST(Trackers, AFixedOffsetBigEndianEulerLayoutLoads) {
  auto r = tracker_config_from_toml(R"(
[trackers]
axis_remap = "x,-z,y"
[trackers.report]
report_id = -1
length = 48
endian = "big"
station_offset = -1
time_offset = -1
position_type = "f32"
position_scale = 10.0
position_components = "-y,x,z"
orientation = "euler"
orientation_type = "fixed32"
orientation_frac_bits = 16
euler_sequence = "xyz"
[trackers.head]
offset = 0
[trackers.patient]
offset = 24
)",
                                     "x.toml");
  ASSERT_TRUE(r) << r.error();
  const auto& p = r->report;
  EXPECT_EQ(p.endian, Endian::Big);
  EXPECT_EQ(p.report_id, -1);
  EXPECT_EQ(p.position_type, FieldType::F32);
  EXPECT_EQ(p.orientation, OrientationKind::Euler);
  EXPECT_EQ(p.orientation_components, "z,y,x");  // the Euler default when only `orientation` changed
  EXPECT_EQ(r->patient.offset, 24);
}

TEST(Trackers, SignedAxesParse) {
  auto a = parse_signed_axes("x,-z, y", "xyz");
  ASSERT_TRUE(a);
  ASSERT_EQ(a->size(), 3u);
  EXPECT_EQ((*a)[1].index, 2);
  EXPECT_EQ((*a)[1].sign, -1);
  EXPECT_EQ((*a)[2].index, 1);
  EXPECT_FALSE(parse_signed_axes("x,x,y", "xyz"));
  EXPECT_FALSE(parse_signed_axes("x,y", "xyz"));
  EXPECT_FALSE(parse_signed_axes("w,x,y,q", "wxyz"));
  EXPECT_FALSE(parse_signed_axes("--x,y,z", "xyz"));
}

TEST(Trackers, BadComponentListIsNamed) {
  EXPECT_EQ(error_of("[trackers.report]\norientation_components = \"w,x,x,z\"\n"),
            "bad.toml:2: key 'trackers.report.orientation_components': expected each of wxyz once, comma-separated, "
            "each optionally negated (e.g. \"x,y,z,w\"), got \"w,x,x,z\"");
  EXPECT_EQ(error_of("[trackers]\naxis_remap = \"x,y\"\n"),
            "bad.toml:2: key 'trackers.axis_remap': expected each of xyz once, comma-separated, each optionally "
            "negated (e.g. \"x,-z,y\"), got \"x,y\"");
}

TEST(Trackers, FieldOutsideTheReportIsNamed) {
  EXPECT_EQ(error_of("[trackers.report]\nlength = 20\n"),
            "bad.toml: key 'trackers.head.offset': expected the sensor's fields (bytes 6 to 25) to lie within the "
            "20-byte report");
  EXPECT_EQ(error_of("[trackers.report]\ntime_offset = 30\n"),
            "bad.toml:2: key 'trackers.report.time_offset': expected 4 byte(s) at offset 30 to lie within the report "
            "(bytes 1 to 31)");
  EXPECT_EQ(error_of("[trackers.report]\nstation_offset = 0\n"),
            "bad.toml:2: key 'trackers.report.station_offset': expected 1 byte(s) at offset 0 to lie within the report "
            "(bytes 1 to 31)");
}

TEST(Trackers, FixedPointBitsAreBounded) {
  EXPECT_EQ(error_of("[trackers.report]\norientation_frac_bits = 16\n"),
            "bad.toml:2: key 'trackers.report.orientation_frac_bits': expected at most 15 fractional bits for a "
            "fixed16 field, got 16");
  EXPECT_EQ(error_of("[trackers.report]\nposition_type = \"u8\"\n"),
            "bad.toml:2: key 'trackers.report.position_type': expected one of \"i16\" | \"i32\" | \"f32\" | "
            "\"fixed16\" | \"fixed32\" | \"none\", got the string \"u8\"");
  EXPECT_EQ(error_of("[trackers.report]\norientation_type = \"none\"\n"),
            "bad.toml:2: key 'trackers.report.orientation_type': expected one of \"i16\" | \"i32\" | \"f32\" | "
            "\"fixed16\" | \"fixed32\", got the string \"none\"");
}

TEST(Trackers, DuplicateStationsAndNoSensorsAreErrors) {
  EXPECT_EQ(error_of("[trackers.patient]\nstation = 1\n"),
            "bad.toml:2: key 'trackers.patient.station': expected a station different from trackers.head's, got 1 "
            "for both");
  EXPECT_EQ(error_of("[trackers.head]\nenabled = false\n[trackers.patient]\nenabled = false\n"),
            "bad.toml:1: key 'trackers.head': expected at least one of trackers.head, trackers.patient, "
            "trackers.stylus enabled, got none");
}

TEST(Trackers, WorkspaceAndToleranceAreChecked) {
  EXPECT_EQ(error_of("[trackers]\nworkspace_min_mm = [0.0, 0.0, 0.0]\nworkspace_max_mm = [1.0, 0.0, 1.0]\n"),
            "bad.toml:3: key 'trackers.workspace_max_mm': expected every component above workspace_min_mm's, got "
            "0.000000 <= 0.000000 at index 1");
  EXPECT_EQ(error_of("[trackers]\nquat_norm_tolerance = 0.0\n"),
            "bad.toml:2: key 'trackers.quat_norm_tolerance': expected a number in [1e-06, 0.5], got the number 0");
  EXPECT_EQ(error_of("[trackers.report]\neuler_sequence = \"zyz\"\n"),
            "bad.toml:2: key 'trackers.report.euler_sequence': expected three distinct axes among x, y, z (e.g. "
            "\"zyx\"), got \"zyz\"");
  EXPECT_EQ(error_of("[trackers.report]\ntime_bits = 24\n"),
            "bad.toml:2: key 'trackers.report.time_bits': expected 16 or 32, got 24");
  EXPECT_EQ(error_of("[trackers.stylus]\nchannel = 3\n"),
            "bad.toml:2: unknown key 'trackers.stylus.channel'; expected one of: enabled, fixed_position_mm, offset, "
            "station, tip_offset_mm");
  EXPECT_EQ(error_of("[trackers.head]\ntip_offset_mm = [0.0, 0.0, 10.0]\n"),
            "bad.toml:2: unknown key 'trackers.head.tip_offset_mm'; expected one of: enabled, fixed_position_mm, offset, "
            "station");
}

TEST(Trackers, AnOrientationOnlyReportTakesEachRolesFixedPosition) {
  auto r = tracker_config_from_toml(R"(
[trackers.report]
length = 16
station_offset = -1
time_offset = -1
position_type = "none"
position_offset = 900
orientation_offset = 0
[trackers.head]
offset = 1
fixed_position_mm = [10.0, -700.0, 1300.0]
[trackers.patient]
enabled = false
)",
                                     "imu.toml");
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->report.position_type, FieldType::None);
  EXPECT_EQ(r->head.fixed_position_mm, (std::array<double, 3>{10.0, -700.0, 1300.0}));
  EXPECT_EQ(error_of("[trackers.head]\nfixed_position_mm = [1.0, 2.0]\n"),
            "bad.toml:2: key 'trackers.head.fixed_position_mm': expected an array of 3 numbers in [-100000, 100000] "
            "mm, got an array of 2");
}

TEST(Trackers, InitFeatureReportsAreHexBytesReportIdFirst) {
  auto r = tracker_config_from_toml("[trackers.hid]\ninit_feature_reports = [\"0x02 0x01\", \"05,FF, 0x0a\"]\n",
                                     "x.toml");
  ASSERT_TRUE(r) << r.error();
  const auto& reports = r->hid.init_feature_reports;
  ASSERT_EQ(reports.size(), 2u);
  EXPECT_EQ(reports[0], (std::vector<std::uint8_t>{0x02, 0x01}));
  EXPECT_EQ(reports[1], (std::vector<std::uint8_t>{0x05, 0xFF, 0x0A}));
  EXPECT_EQ(error_of("[trackers.hid]\ninit_feature_reports = [\"0x02 0x01\", \"0x02 0x1G\"]\n"),
            "bad.toml:2: key 'trackers.hid.init_feature_reports': expected hex bytes, report id first (e.g. \"0x02 "
            "0x01\"), got \"0x02 0x1G\" at index 1");
  EXPECT_EQ(error_of("[trackers.hid]\ninit_feature_reports = [\"\"]\n"),
            "bad.toml:2: key 'trackers.hid.init_feature_reports': expected hex bytes, report id first (e.g. \"0x02 "
            "0x01\"), got \"\" at index 0");
  EXPECT_EQ(error_of("[trackers.hid]\ninit_feature_reports = [\"0x123\"]\n"),
            "bad.toml:2: key 'trackers.hid.init_feature_reports': expected hex bytes, report id first (e.g. \"0x02 "
            "0x01\"), got \"0x123\" at index 0");
  EXPECT_EQ(error_of("[trackers.hid]\ninit_feature_reports = [2]\n"),
            "bad.toml:2: key 'trackers.hid.init_feature_reports': expected an array of strings, got the integer 2 at "
            "index 0");
}

TEST(Trackers, IgtlTableNamesTheServerAndTheDeviceOfEachRole) {
  auto r = tracker_config_from_toml(R"(
[trackers]
source = "igtl"
[trackers.igtl]
host = "plus.lab"
port = 18945
head = ""
patient = "ReferenceToTracker"
scale = 1000.0
rigid_tolerance = 0.01
)",
                                     "x.toml");
  ASSERT_TRUE(r) << r.error();
  const auto& g = r->igtl;
  EXPECT_EQ(r->source, lungar::drivers::TrackerSource::Igtl);
  EXPECT_EQ(g.host, "plus.lab");
  EXPECT_EQ(g.port, 18945);
  EXPECT_EQ(g.head, "");
  EXPECT_EQ(g.patient, "ReferenceToTracker");
  EXPECT_EQ(g.stylus, "StylusTipToTracker");  // the default, PLUS's naming
  EXPECT_DOUBLE_EQ(g.scale, 1000.0);
  EXPECT_EQ(lungar::drivers::TrackerConfig{}.igtl.port, 18944);
  EXPECT_EQ(error_of("[trackers.igtl]\nport = 0\n"),
            "bad.toml:2: key 'trackers.igtl.port': expected an integer in [1, 65535] (TCP port), got the integer 0");
  EXPECT_EQ(error_of("[trackers.igtl]\npatient = \"ThisNameIsLongerThan20\"\n"),
            "bad.toml:2: key 'trackers.igtl.patient': expected a device name of at most 20 characters (OpenIGTLink's "
            "limit), got \"ThisNameIsLongerThan20\"");
  EXPECT_EQ(error_of("[trackers.igtl]\nhead = \"\"\npatient = \"\"\nstylus = \"\"\n"),
            "bad.toml:3: key 'trackers.igtl.patient': expected a device name for at least one of head, patient, "
            "stylus, got none");
}
