// Tests of drivers/tracker/tracker_config_toml: [trackers] written and read from one field list round-trips.
// write(read(x)) gives back x's keys and values for config/default.toml and the shipped profiles; read(write(c))
// gives back c for a config whose every key differs from the default; the .trk headers the former hand-written
// writer made still load.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "drivers/decode/report_layout.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/trk/trk_reader.h"
#include "test_data.h"

using namespace lungar;
using namespace lungar::drivers;

namespace {

/// The [trackers] table of a TOML document.
toml::table trackers_table(const std::string& text, const std::string& name) {
  toml::table doc = toml::parse(text, name);
  const toml::table* t = doc["trackers"].as_table();
  EXPECT_NE(t, nullptr) << name << " has no [trackers]";
  return t ? *t : toml::table{};
}

toml::table trackers_table_of_file(const std::filesystem::path& path) {
  toml::table doc = toml::parse_file(path.string());
  const toml::table* t = doc["trackers"].as_table();
  EXPECT_NE(t, nullptr) << path << " has no [trackers]";
  return t ? *t : toml::table{};
}

/// Whether two nodes have the same type and value (tables and arrays element by element).
bool same(const toml::node& a, const toml::node& b) {
  return a.type() == b.type() && a.visit([&](const auto& x) { return x == static_cast<decltype(x)>(b); });
}

/// Every key of `part` (tables recursively) with an equal value, type included, in `whole`: what differs, one
/// "path: ..." line each.
void missing_from(const toml::table& whole, const toml::table& part, const std::string& path,
                  std::vector<std::string>& out) {
  for (const auto& [key, node] : part) {
    const std::string at = path + "." + std::string(key.str());
    const toml::node* other = whole.get(key.str());
    if (!other) {
      out.push_back(at + ": not written");
    } else if (node.is_table() && other->is_table()) {
      missing_from(*other->as_table(), *node.as_table(), at, out);
    } else if (!same(node, *other)) {
      out.push_back(at + ": written differently");
    }
  }
}

/// The keys (tables recursively) whose values are equal in `a` and `b`.
void equal_keys(const toml::table& a, const toml::table& b, const std::string& path, std::vector<std::string>& out) {
  for (const auto& [key, node] : a) {
    const std::string at = path + "." + std::string(key.str());
    const toml::node* other = b.get(key.str());
    if (node.is_table() && other && other->is_table()) {
      equal_keys(*node.as_table(), *other->as_table(), at, out);
    } else if (other && same(node, *other)) {
      out.push_back(at);
    }
  }
}

/// A valid config in which every key of [trackers] and its tables differs from the default, with strings that
/// need escaping and doubles that need every digit.
TrackerConfig every_key_changed() {
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.mock.trajectory = "head_orbit";
  t.mock.rate_hz = 100.0 + 1.0 / 3.0;
  t.mock.noise_mm = 0.1 + 0.2;
  t.mock.dropout = 0.25;
  t.replay_file = "logs/a \"quoted\" \\ back\tslash.trk";
  t.replay_realtime = false;
  t.replay_loop = true;
  t.replay_truncated = true;
  t.stale_ms = 123.456;
  t.reopen_backoff_ms = 500.0;
  t.quat_norm_tolerance = 1e-3;
  t.workspace_min_mm = {-1000.5, -2000.0, -1e-3};
  t.workspace_max_mm = {1000.0, 2000.25, 3.0};
  t.axis_remap = "x,-z,y";
  t.world_offset_mm = {1.5, -2.5, 1e-9};
  t.hid = {0x1532, 0x0b00, "SN\x01\xc3\xbc", "/dev/hidraw3", 20.5, {{0x02, 0x01}, {0x00, 0xff, 0x10}}};
  t.igtl = {"tracker.local", 1, "H", "", "StylusTip12345678901", 1000.0, 2e-7, 10.0};
  t.plus = {"Headset", "Phantom", "Pointer"};
  ReportConfig& r = t.report;
  r.report_id = -1;
  r.length = 64;
  r.endian = Endian::Big;
  r.station_offset = -1;
  r.time_offset = 60;
  r.time_bits = 16;
  r.time_tick_us = 0.5;
  r.position_offset = 2;
  r.position_type = FieldType::Fixed32;
  r.position_frac_bits = 8;
  r.position_scale = 0.001;
  r.position_components = "-y,x,z";
  r.orientation = OrientationKind::Euler;
  r.orientation_offset = 16;
  r.orientation_type = FieldType::Fixed32;
  r.orientation_frac_bits = 16;
  r.orientation_scale = 0.5;
  r.orientation_components = "x,-y,z";
  r.euler_sequence = "xyz";
  t.head = {false, 11, 7, {1.0, 2.0, 3.0}};
  t.patient = {false, 12, 8, {-1.0, -2.0, -3.0}};
  t.stylus = {true, 13, 9, {0.5, 0.25, 0.125}, {1.5, -2.25, -150.125}};
  return t;
}

}  // namespace

// write(read(x)) == x: the shipped default.toml names every key of [trackers], so what the writer writes of the
// defaults it reads is that table, key for key and value for value (types included).
TEST(TrackerConfigToml, WritingTheShippedDefaultsGivesTheirTable) {
  const std::filesystem::path path = std::filesystem::path(LUNGAR_SOURCE_DIR) / "config" / "default.toml";
  auto read = tracker_config_from_file(path.string());
  ASSERT_TRUE(read) << read.error();
  EXPECT_TRUE(*read == TrackerConfig{});
  const std::string written = tracker_config_to_toml(*read);
  const toml::table shipped = trackers_table_of_file(path);
  const toml::table back = trackers_table(written, "written");
  std::vector<std::string> diff;
  missing_from(back, shipped, "trackers", diff);
  missing_from(shipped, back, "trackers", diff);  // and nothing default.toml does not have
  EXPECT_TRUE(diff.empty()) << ::testing::PrintToString(diff) << "\n" << written;
}

// write(read(x)) == x for each shipped profile: every key it sets is written back as it was, and what is
// written reads back to the same config.
TEST(TrackerConfigToml, ShippedProfilesRoundTrip) {
  const std::filesystem::path dir = std::filesystem::path(LUNGAR_SOURCE_DIR) / "config" / "trackers";
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().string());
    auto read = tracker_config_from_file(entry.path().string());
    ASSERT_TRUE(read) << read.error();
    EXPECT_FALSE(*read == TrackerConfig{});
    const std::string written = tracker_config_to_toml(*read);
    std::vector<std::string> diff;
    missing_from(trackers_table(written, "written"), trackers_table_of_file(entry.path()), "trackers", diff);
    EXPECT_TRUE(diff.empty()) << ::testing::PrintToString(diff) << "\n" << written;
    auto again = tracker_config_from_toml(written, "written");
    ASSERT_TRUE(again) << again.error() << "\n" << written;
    EXPECT_TRUE(*again == *read) << written;
    ++n;
  }
  EXPECT_GE(n, 3);
}

// read(write(c)) == c for a config whose every written key differs from the default's: a key the writer drops,
// misspells or writes imprecisely reads back as the default, or not at all, and fails here.
TEST(TrackerConfigToml, AConfigWithEveryKeyChangedRoundTrips) {
  const TrackerConfig c = every_key_changed();
  const std::string written = tracker_config_to_toml(c);
  std::vector<std::string> unchanged;
  equal_keys(trackers_table(tracker_config_to_toml(TrackerConfig{}), "defaults"), trackers_table(written, "c"),
             "trackers", unchanged);
  EXPECT_TRUE(unchanged.empty()) << "keys the test config leaves at their default: "
                                 << ::testing::PrintToString(unchanged);
  auto back = tracker_config_from_toml(written, "c");
  ASSERT_TRUE(back) << back.error() << "\n" << written;
  EXPECT_TRUE(*back == c) << written;
  EXPECT_EQ(back->hid.serial, c.hid.serial);
  EXPECT_EQ(back->replay_file, c.replay_file);
  EXPECT_EQ(back->hid.init_feature_reports, c.hid.init_feature_reports);
  EXPECT_EQ(back->mock.rate_hz, c.mock.rate_hz);  // exactly: every digit written
  EXPECT_EQ(back->mock.noise_mm, c.mock.noise_mm);
  EXPECT_EQ(tracker_config_to_toml(*back), written);
}

// The reader's checks run on what is read: a file's error names its line and key, as the settings loader's does.
TEST(TrackerConfigToml, ReadingChecksAcrossKeys) {
  EXPECT_EQ(tracker_config_from_toml("[trackers.report]\nposition_type = \"i16\"\nposition_frac_bits = 4\n", "x")
                .error(),
            "x:3: key 'trackers.report.position_frac_bits': expected at most 0 fractional bits for a i16 field, got 4");
  EXPECT_EQ(tracker_config_from_toml("[trackers]\nsource = \"replay\"\n", "x").error(),
            "x:1: key 'trackers.replay_file': expected a .trk file when source = \"replay\", got nothing");
  EXPECT_EQ(tracker_config_from_toml("[trackers.plus]\npatient = \"HMD\"\n", "x").error(),
            "x:2: key 'trackers.plus.patient': expected a different tool for each of head, patient and stylus, got "
            "\"HMD\", \"HMD\", \"Stylus\"");
  EXPECT_NE(tracker_config_from_toml("[trackers.plus]\nstylus = \"StylusToTracker\"\n", "x")
                .error()
                .find("x:2: key 'trackers.plus.stylus': expected a PLUS tool name of 1 to 17 characters without \"To\""),
            std::string::npos);
  // Tables other than [trackers] belong to others (a whole config file may be given).
  auto whole = tracker_config_from_toml("[display]\noutput = \"window\"\n[trackers]\nstale_ms = 50.0\n", "x");
  ASSERT_TRUE(whole) << whole.error();
  EXPECT_EQ(whole->stale_ms, 50.0);
}

// The committed logs' headers carry the layout the former writer wrote (a subset of the keys): they still load,
// and describe the layout they were made with.
TEST(TrackerConfigToml, CommittedLogHeadersStillLoad) {
  for (const char* name : {"upright_to_supine.trk", "head_orbit_noisy.trk"}) {
    SCOPED_TRACE(name);
    auto log = load_trk(lungar::testing::tracker_data(name));
    ASSERT_TRUE(log) << log.error();
    ASSERT_FALSE(log->header.layout_toml.empty());
    auto t = tracker_config_from_toml(log->header.layout_toml, name);
    ASSERT_TRUE(t) << t.error();
    EXPECT_TRUE(t->report == ReportConfig{});
    EXPECT_TRUE(t->head == TrackerConfig{}.head);
    EXPECT_TRUE(t->igtl == IgtlConfig{});
    EXPECT_TRUE(make_layout(*t)) << make_layout(*t).error();
  }
}
