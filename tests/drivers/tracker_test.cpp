// Tests of drivers/tracker through make_tracker(): replay of the committed recording against its expected
// poses, mock streaming with recording to .trk, staleness, and errors for bad settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/mock/mock_reports.h"
#include "drivers/tracker/tracker_config_toml.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "drivers/trk/trk_reader.h"
#include "drivers/trk/trk_writer.h"
#include "test_data.h"
#include "tracker_test_support.h"

using namespace lungar;
using namespace lungar::drivers;
using namespace lungar::testing;

namespace {

struct ExpectedRow {
  std::string role;
  std::int64_t t_device_ns;
  std::array<double, 3> p;
  std::array<double, 4> q;
};

std::vector<ExpectedRow> read_expected(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<ExpectedRow> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string f[12];
    for (auto& x : f) std::getline(s, x, ',');
    if (f[4] != "ok") continue;
    rows.push_back({f[3], std::stoll(f[2]), {std::stod(f[5]), std::stod(f[6]), std::stod(f[7])},
                    {std::stod(f[8]), std::stod(f[9]), std::stod(f[10]), std::stod(f[11])}});
  }
  return rows;
}

}  // namespace

// libsurvive-style: the committed recording, replayed as fast as possible, gives every expected pose.
TEST(Tracker, ReplayOfTheCommittedRecordingMatchesItsExpectedPoses) {
  constexpr double kPosTolMm = 1e-3;     // the CSV keeps 4 decimals
  constexpr double kQuatTol = 1e-5;      // and 6 for quaternion components
  const auto expected = read_expected(lungar::testing::tracker_data("upright_to_supine.expected.csv"));
  ASSERT_EQ(expected.size(), 750u);
  Collector collected;
  TrackerOptions o = collecting(collected);
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.replay_file = lungar::testing::tracker_data("upright_to_supine.trk");
  t.replay_realtime = false;
  auto made = make_tracker(t, o);
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(eventually([&] { return (*made)->finished(); }));
  (*made)->stop();
  const auto got = collected.copy();
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(to_string(got[k].role), expected[k].role);
    EXPECT_EQ(got[k].t_device_ns, expected[k].t_device_ns);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[k].position_mm[i], expected[k].p[i], kPosTolMm);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[k].orientation_wxyz[i], expected[k].q[i], kQuatTol);
  }
  const TrackerStats s = (*made)->stats();
  EXPECT_EQ(s.accepted, 750u);
  EXPECT_EQ(s.malformed, 0u);
  // The last patient pose is supine.
  const PoseSample last = (*made)->latest(Role::Patient, monotonic_ns());
  EXPECT_NEAR((last.orientation() * Eigen::Vector3d::UnitY()).z(), -1.0, 1e-3);
}

TEST(Tracker, NoisyRecordingWithDropoutsReplaysWithoutMalformedReports) {
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.replay_file = lungar::testing::tracker_data("head_orbit_noisy.trk");
  t.replay_realtime = false;
  auto made = make_tracker(t, quiet());
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(eventually([&] { return (*made)->finished(); }));
  const auto log = load_trk(t.replay_file);
  ASSERT_TRUE(log);
  EXPECT_LT(log->records.size(), 375u);  // 5 % of 375 dropped
  EXPECT_EQ((*made)->stats().accepted, log->records.size());
  EXPECT_EQ((*made)->stats().malformed, 0u);
}

TEST(Tracker, MockStreamsGoesStaleWhenStoppedAndRecordsWhatItRead) {
  const auto dir = std::filesystem::temp_directory_path() / ("lungar_tracker_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string rec = (dir / "mock.trk").string();
  TrackerConfig t;
  t.mock.rate_hz = 200;  // many reports quickly
  t.stale_ms = 50;
  TrackerOptions o = quiet();
  o.record_path = rec;
  struct Logged {
    std::mutex mutex;
    std::vector<std::string> lines;
  };
  auto logged = std::make_shared<Logged>();
  o.log = [logged](const std::string& line) {
    const std::lock_guard<std::mutex> lock(logged->mutex);
    logged->lines.push_back(line);
  };
  auto made = make_tracker(t, o);
  ASSERT_TRUE(made) << made.error();
  Tracker& tr = **made;
  EXPECT_EQ(tr.describe(), "mock upright_to_supine");
  // --record says where it writes (it did not: a bare --record's file was found only in the folder).
  {
    const std::lock_guard<std::mutex> lock(logged->mutex);
    EXPECT_TRUE(std::any_of(logged->lines.begin(), logged->lines.end(), [&](const std::string& line) {
      return line.find("recording the tracker's reports into " + rec) != std::string::npos;
    })) << "no line names " << rec;
  }
  ASSERT_TRUE(eventually([&] { return tr.stats().accepted >= 100; }));
  EXPECT_EQ(tr.state(), TrackerState::Streaming);
  const PoseSample head = tr.latest(Role::Head, monotonic_ns());
  EXPECT_TRUE(head.valid());
  EXPECT_NEAR(head.orientation().norm(), 1.0, 1e-12);
  EXPECT_GE(tr.history(Role::Head).count, 2u);
  EXPECT_TRUE(tr.predicted(Role::Head, monotonic_ns() + 10'000'000, 50'000'000).valid());
  EXPECT_FALSE(tr.latest(Role::Stylus, monotonic_ns()).valid());  // disabled by default
  // The rate is measured over whole seconds: after one, both roles have a rate and the total is their sum.
  ASSERT_TRUE(eventually([&] { return tr.stats().rate_hz > 0; }, 5.0));
  const TrackerStats rs = tr.stats();
  EXPECT_GT(rs.role_rate_hz[static_cast<int>(Role::Head)], 0.0);
  EXPECT_EQ(rs.role_rate_hz[static_cast<int>(Role::Stylus)], 0.0);
  EXPECT_NEAR(rs.rate_hz, rs.role_rate_hz[0] + rs.role_rate_hz[1], 1e-9);
  tr.stop();
  const TrackerStats s = tr.stats();
  EXPECT_EQ(s.malformed, 0u);
  EXPECT_EQ(s.recorded, s.reports);
  // Read later than stale_ms: the last pose stays, marked stale.
  const PoseSample later = tr.latest(Role::Patient, monotonic_ns() + 60'000'000);
  EXPECT_TRUE(later.valid());
  EXPECT_TRUE(later.stale());
  auto log = load_trk(rec);
  ASSERT_TRUE(log) << log.error();
  EXPECT_EQ(log->records.size(), s.reports);
  EXPECT_EQ(log->header.field("source"), "mock");
  EXPECT_FALSE(log->header.layout_toml.empty());
  EXPECT_EQ(log->records.front().source, TrkSource::Mock);
}

// A truncated .trk (a recording cut short) replayed without a word, though lungar-trk info knew: it is refused in
// one line naming the file and the way to replay it anyway, which then replays the records it holds.
TEST(Tracker, ATruncatedLogIsRefusedUnlessReplayTruncatedIsGiven) {
  const std::filesystem::path cut =
      std::filesystem::temp_directory_path() / ("lungar_truncated_" + std::to_string(::getpid()) + ".trk");
  std::filesystem::copy_file(lungar::testing::tracker_data("upright_to_supine.trk"), cut,
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, std::filesystem::file_size(cut) - 7);
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.replay_file = cut.string();
  t.replay_realtime = false;
  const auto refused = make_tracker(t, quiet());
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().rfind(cut.string() + ": the log is truncated", 0), 0u) << refused.error();
  EXPECT_NE(refused.error().find("--replay-truncated"), std::string::npos) << refused.error();
  EXPECT_EQ(refused.error().find('\n'), std::string::npos);
  t.replay_truncated = true;
  const auto replayed = make_tracker(t, quiet());
  EXPECT_TRUE(replayed) << replayed.error();
  std::filesystem::remove(cut);
}

TEST(Tracker, BadSettingsAreOneLineErrors) {
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.replay_file = "/nonexistent/x.trk";
  EXPECT_EQ(make_tracker(t, quiet()).error(),
            "/nonexistent/x.trk: cannot open the tracker log: expected a readable .trk file");
  t = {};
  t.mock.trajectory = "somersault";
  EXPECT_EQ(make_tracker(t, quiet()).error(),
            "trackers.mock_trajectory: expected static | upright_to_supine | head_orbit | bedside, got \"somersault\"");
  t = {};
  t.report.length = 8;
  EXPECT_EQ(make_tracker(t, quiet()).error(),
            "tracker report layout: trackers.head.offset: expected the sensor's fields inside the report");
  t = {};
  TrackerOptions o = quiet();
  o.record_path = "/nonexistent/rec.trk";
  EXPECT_EQ(make_tracker(t, o).error().rfind("/nonexistent/rec.trk: cannot create the tracker log", 0), 0u);
}

TEST(Tracker, AnAbsentHidDeviceIsDisconnectedNotAnError) {
  TrackerConfig t;
  t.source = TrackerSource::Hid;
  t.hid.vendor_id = 0xDEAD;  // no such device on this machine
  t.hid.product_id = 0xBEEF;
  t.reopen_backoff_ms = 5;
  auto made = make_tracker(t, quiet());
  ASSERT_TRUE(made) << made.error();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a few reopen attempts with back-off
  const TrackerStats s = (*made)->stats();
  EXPECT_NE(s.state, TrackerState::Streaming);
  EXPECT_EQ(s.opens, 0u);
  EXPECT_EQ(s.reports, 0u);
  EXPECT_FALSE((*made)->latest(Role::Head, monotonic_ns()).valid());
  EXPECT_EQ((*made)->describe(), "hid dead:beef");
}

TEST(Tracker, ALoopingReplayContinuesDeviceTimeAcrossTheLoop) {
  TrackerConfig t;
  t.source = TrackerSource::Replay;
  t.replay_file = lungar::testing::tracker_data("upright_to_supine.trk");
  t.replay_realtime = false;
  t.replay_loop = true;
  std::mutex m;
  std::vector<std::int64_t> times;
  TrackerOptions o = quiet();
  o.on_sample = [&](const PoseSample& s) {
    std::lock_guard lock(m);
    if (s.role == Role::Patient && times.size() < 800) times.push_back(s.t_device_ns);
  };
  auto made = make_tracker(t, o);
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(eventually([&] {
    std::lock_guard lock(m);
    return times.size() >= 800;  // 375 patient samples per pass: more than two passes
  }));
  (*made)->stop();
  EXPECT_EQ((*made)->stats().malformed, 0u);  // the restart is not "time backwards"
  EXPECT_EQ((*made)->stats().reconnects, 0u);
  for (std::size_t k = 1; k < times.size(); ++k) ASSERT_GE(times[k], times[k - 1]) << k;
}

// A replayed log says so when its header names another report layout than the config's: the committed log's
// header (written by an older writer, a subset of the keys) names the default layout, and the source it was made
// with is no difference.
TEST(Tracker, AReplayedLogMadeWithAnotherLayoutSaysSo) {
  for (const bool another : {false, true}) {
    SCOPED_TRACE(another);
    TrackerConfig t;
    t.source = TrackerSource::Replay;
    t.replay_file = lungar::testing::tracker_data("upright_to_supine.trk");
    t.replay_realtime = false;
    if (another) t.report.position_scale = 0.1;
    std::mutex m;
    std::vector<std::string> lines;
    TrackerOptions o = quiet();
    o.log = [&](const std::string& line) {
      std::lock_guard lock(m);
      lines.push_back(line);
    };
    auto made = make_tracker(t, o);
    ASSERT_TRUE(made) << made.error();
    (*made)->stop();
    std::lock_guard lock(m);
    const auto said = std::count_if(lines.begin(), lines.end(), [](const std::string& l) {
      return l.find("the log was recorded with another report layout than the config's") != std::string::npos;
    });
    EXPECT_EQ(said, another ? 1 : 0) << ::testing::PrintToString(lines);
  }
}

// Device time is counted in the layout's tick (time_tick_us), not a fixed microsecond: the mock stamps its
// reports k / rate seconds apart in ticks of 10 us, and the samples come out k / rate seconds apart.
TEST(Tracker, DeviceTimeIsCountedInTheLayoutsTick) {
  TrackerConfig t;
  t.mock.rate_hz = 250;
  t.report.time_tick_us = 10.0;
  std::mutex m;
  std::vector<std::int64_t> times;
  TrackerOptions o = quiet();
  o.on_sample = [&](const PoseSample& s) {
    std::lock_guard lock(m);
    if (s.role == Role::Head) times.push_back(s.t_device_ns);
  };
  auto made = make_tracker(t, o);
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(eventually([&] {
    std::lock_guard lock(m);
    return times.size() >= 20;
  }));
  (*made)->stop();
  for (std::size_t k = 1; k < 20; ++k) EXPECT_EQ(times[k] - times[0], static_cast<std::int64_t>(k) * 4'000'000) << k;
}

// Replay honours an orientation-only layout: every sample of a synthesized IMU log sits at the head's fixed
// position and turns as the trajectory did.
TEST(Tracker, ReplayOfAnOrientationOnlyLogKeepsTheFixedPosition) {
  auto loaded = drivers::tracker_config_from_file(std::string(LUNGAR_SOURCE_DIR) + "/config/trackers/sparkfun-9dof-razor.toml");
  ASSERT_TRUE(loaded) << loaded.error();
  TrackerConfig t = *loaded;
  t.mock.trajectory = "head_orbit";
  const auto layout = make_layout(t);
  ASSERT_TRUE(layout) << layout.error();
  const auto path = std::filesystem::temp_directory_path() / ("lungar_imu_" + std::to_string(::getpid()) + ".trk");
  TrkWriter w;
  TrkHeader h;
  h.layout_toml = tracker_config_to_toml(t);
  ASSERT_EQ(w.open(path.string(), h, TrkWriter::Mode::Atomic).error(), "");
  MockReports reports(t.mock, *layout);
  for (std::int64_t k = 0; k < 50; ++k) {
    reports.tick(k, [&](std::span<const std::uint8_t> bytes) {
      ASSERT_TRUE(w.append(TrkSource::Synth, k * 16'000'000, bytes));
    });
  }
  ASSERT_EQ(w.commit().error(), "");
  TrackerConfig rs = t;
  rs.source = TrackerSource::Replay;
  rs.replay_file = path.string();
  rs.replay_realtime = false;
  Collector collected;
  TrackerOptions o = collecting(collected);
  auto made = make_tracker(rs, o);
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(eventually([&] { return (*made)->finished(); }));
  (*made)->stop();
  std::filesystem::remove(path);
  const auto got = collected.copy();
  ASSERT_EQ(got.size(), 50u);
  for (std::size_t k = 0; k < got.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(got[k].position_mm, t.head.fixed_position_mm);
    const PoseSample want = *mock_pose("head_orbit", Role::Head, static_cast<double>(k) / t.mock.rate_hz);
    EXPECT_LT(got[k].orientation().angularDistance(want.orientation()), 1e-6);
  }
}
