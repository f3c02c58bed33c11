// Hardware-in-the-loop without hardware: real hidapi (hidraw backend) on a tracker emulated by umockdev.
// Reports written to the device must come out as the same poses as replaying the same reports; unplug and
// replug must go stale -> streaming without a restart; malformed reports are counted and never applied.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <mutex>
#include <thread>
#include <vector>

#include <hidapi/hidapi.h>

#include "drivers/decode/encoder.h"
#include "drivers/hid/hid_interface.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "drivers/trk/trk_reader.h"
#include "test_data.h"
#include "tracker_test_support.h"
#include "umockdev_tracker.h"

using namespace lungar;
using namespace lungar::drivers;
using namespace lungar::testing;

namespace {

TrackerConfig hid_settings() {
  TrackerConfig t;
  t.source = TrackerSource::Hid;
  t.hid.vendor_id = 0x1234;
  t.hid.product_id = 0x5678;
  t.reopen_backoff_ms = 20;  // tests wait for reconnects; keep the back-off short
  t.stale_ms = 100;
  return t;
}

class HidUmockdev : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!UmockdevTracker::available()) GTEST_SKIP() << "not under umockdev-wrapper";
    ASSERT_TRUE(device.plug({})) << device.error();
  }
  UmockdevTracker device;
};

}  // namespace

TEST_F(HidUmockdev, ProberFindsTheEmulatedDeviceByIdsAndSerial) {
  HidConfig h;
  h.vendor_id = 0x1234;
  h.product_id = 0x5678;
  h.serial = "SN0001";
  hid_init();
  auto found = hid_probe(h);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->path, device.dev_path());
  EXPECT_EQ(found->serial, "SN0001");
  h.serial = "OTHER";
  EXPECT_FALSE(hid_probe(h));
}

TEST_F(HidUmockdev, ReportsComeOutAsTheSamePosesAsReplay) {
  const std::string file = lungar::testing::tracker_data("upright_to_supine.trk");
  auto log = load_trk(file);
  ASSERT_TRUE(log) << log.error();

  Collector via_hid;
  auto hid = make_tracker(hid_settings(), collecting(via_hid));
  ASSERT_TRUE(hid) << hid.error();
  ASSERT_TRUE(eventually([&] { return (*hid)->stats().opens >= 1; }));
  // Flow control: the emulated node is a pseudo-terminal whose line discipline holds 4 KiB; writing past
  // that splits a report across reads. A real device sends at its rate; here at most 64 reports are in flight.
  std::size_t written = 0;
  for (const auto& rec : log->records) {
    ASSERT_TRUE(eventually([&] { return written < via_hid.size() + 64; }));
    ASSERT_TRUE(device.write(rec.report));
    ++written;
  }
  ASSERT_TRUE(eventually([&] { return via_hid.size() >= log->records.size(); }))
      << via_hid.size() << " of " << log->records.size();

  const auto a = via_hid.copy();
  expect_bit_identical(a, replay_all(file));
  EXPECT_EQ((*hid)->stats().malformed, 0u);
  EXPECT_EQ((*hid)->stats().accepted, log->records.size());
  const double burst_s = (a.back().t_arrival_ns - a.front().t_arrival_ns) * 1e-9;
  std::printf("[ MEASURED ] hid via umockdev, %zu reports written with 64 in flight: read at %.0f reports/s\n", a.size(),
              (a.size() - 1) / burst_s);
}

TEST_F(HidUmockdev, UnplugGoesStaleAndReplugStreamsAgainWithoutARestart) {
  Collector c;
  auto made = make_tracker(hid_settings(), collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(eventually([&] { return t.stats().opens >= 1; }));

  auto layout = make_layout(hid_settings());
  ASSERT_TRUE(layout);
  std::array<std::uint8_t, 32> buf{};
  auto send = [&](double x_mm, std::uint32_t ticks) {
    PoseSample p;
    p.role = Role::Patient;
    p.position_mm = {x_mm, 0, 1000};
    encode_report(*layout, std::span<const PoseSample>(&p, 1), ticks, buf);
    return device.write(buf);
  };
  ASSERT_TRUE(send(10.0, 1000));
  ASSERT_TRUE(eventually([&] { return c.size() == 1; }));
  EXPECT_EQ(t.state(), TrackerState::Streaming);
  ASSERT_TRUE(eventually([&] { return t.state() == TrackerState::Stale; }));  // silent for stale_ms

  device.unplug();
  // Lost: either the read fails (disconnected) or the silence makes it stale and the prober misses it.
  ASSERT_TRUE(eventually([&] { return t.state() == TrackerState::Disconnected; }))
      << "state " << to_string(t.state());
  const PoseSample kept = t.latest(Role::Patient, monotonic_ns());
  EXPECT_TRUE(kept.valid());
  EXPECT_TRUE(kept.stale());  // the picture keeps the last pose, marked stale
  EXPECT_DOUBLE_EQ(kept.position_mm[0], 10.0);

  ASSERT_TRUE(device.plug({})) << device.error();
  ASSERT_TRUE(eventually([&] { return t.stats().opens == 2; })) << "state " << to_string(t.state());
  ASSERT_TRUE(send(20.0, 5));  // a device clock that restarted after the replug is not "backwards"
  ASSERT_TRUE(eventually([&] { return c.size() == 2; }));
  EXPECT_EQ(t.state(), TrackerState::Streaming);
  const PoseSample fresh = t.latest(Role::Patient, monotonic_ns());
  EXPECT_FALSE(fresh.stale());
  EXPECT_DOUBLE_EQ(fresh.position_mm[0], 20.0);
  EXPECT_GT(fresh.t_device_ns, kept.t_device_ns);
  EXPECT_EQ(t.stats().reconnects, 1u);
  EXPECT_EQ(t.stats().malformed, 0u);
}

TEST_F(HidUmockdev, MalformedReportsAreCountedAndNeverApplied) {
  Collector c;
  auto made = make_tracker(hid_settings(), collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(eventually([&] { return t.stats().opens >= 1; }));
  auto layout = make_layout(hid_settings());
  std::array<std::uint8_t, 32> good{};
  PoseSample p;
  p.role = Role::Patient;
  p.position_mm = {1, 2, 3};
  encode_report(*layout, std::span<const PoseSample>(&p, 1), 100, good);
  ASSERT_TRUE(device.write(good));
  ASSERT_TRUE(eventually([&] { return t.stats().accepted == 1; }));

  auto bad = good;
  bad[0] = 7;  // unknown report id
  ASSERT_TRUE(device.write(bad));
  bad = good;
  bad[1] = 9;  // unknown station
  ASSERT_TRUE(device.write(bad));
  bad = good;
  bad[18] = 0;  // w = 0 with x = y = z = 0: norm 0
  bad[19] = 0;
  ASSERT_TRUE(device.write(bad));
  PoseSample far = p;
  far.position_mm = {1, 2, 9000};  // outside the default workspace (3 m)
  encode_report(*layout, std::span<const PoseSample>(&far, 1), 101, bad);
  ASSERT_TRUE(device.write(bad));
  encode_report(*layout, std::span<const PoseSample>(&p, 1), 50, bad);  // device time backwards
  ASSERT_TRUE(device.write(bad));
  ASSERT_TRUE(eventually([&] { return t.stats().reports == 6; }));
  const TrackerStats s = t.stats();
  EXPECT_EQ(s.accepted, 1u);
  EXPECT_EQ(s.malformed, 5u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::UnknownReportId)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::UnknownStation)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::QuaternionNorm)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::OutsideWorkspace)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::TimeBackwards)], 1u);
  EXPECT_EQ(c.size(), 1u);
  EXPECT_EQ(t.latest(Role::Patient, monotonic_ns()).position_mm, p.position_mm);
}

// Measurement, not a timing assertion: reports written every 16 ms through the emulated device; the delivered
// rate and inter-arrival jitter are printed (see the report). Only "every report arrived" is asserted.
TEST_F(HidUmockdev, DeliveredRateAndJitterAt16ms) {
  Collector c;
  auto made = make_tracker(hid_settings(), collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(eventually([&] { return t.stats().opens >= 1; }));
  auto layout = make_layout(hid_settings());
  std::array<std::uint8_t, 32> buf{};
  const int n = 125;  // 2 s at 62.5 Hz
  std::vector<std::int64_t> written_ns(n);
  auto next = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    PoseSample p;
    p.role = Role::Head;
    p.position_mm = {static_cast<double>(k), 0, 1500};
    encode_report(*layout, std::span<const PoseSample>(&p, 1), static_cast<std::uint32_t>(k * 16000), buf);
    written_ns[k] = monotonic_ns();
    ASSERT_TRUE(device.write(buf));
    next += std::chrono::microseconds(16000);
    std::this_thread::sleep_until(next);
  }
  ASSERT_TRUE(eventually([&] { return c.size() == static_cast<std::size_t>(n); })) << c.size();
  const auto s = c.copy();
  std::vector<double> gaps_ms;
  for (std::size_t k = 1; k < s.size(); ++k) gaps_ms.push_back((s[k].t_arrival_ns - s[k - 1].t_arrival_ns) * 1e-6);
  std::sort(gaps_ms.begin(), gaps_ms.end());
  // Write -> published sample: what the reader thread adds, apart from the writer's own scheduling.
  std::vector<double> latency_ms;
  for (const auto& x : s) latency_ms.push_back((x.t_arrival_ns - written_ns[static_cast<std::size_t>(x.position_mm[0])]) * 1e-6);
  std::sort(latency_ms.begin(), latency_ms.end());
  const double span_s = (s.back().t_arrival_ns - s.front().t_arrival_ns) * 1e-9;
  const double rate = (s.size() - 1) / span_s;
  std::printf("[ MEASURED ] hid via umockdev: %zu reports, rate %.2f Hz, inter-arrival p50 %.3f ms, p99 %.3f ms, "
              "max %.3f ms\n",
              s.size(), rate, gaps_ms[gaps_ms.size() / 2], gaps_ms[gaps_ms.size() * 99 / 100], gaps_ms.back());
  std::printf("[ MEASURED ] hid via umockdev: write -> read latency p50 %.3f ms, p99 %.3f ms, max %.3f ms\n",
              latency_ms[latency_ms.size() / 2], latency_ms[latency_ms.size() * 99 / 100], latency_ms.back());
  RecordProperty("rate_hz", std::to_string(rate));
  EXPECT_EQ(t.stats().malformed, 0u);
}

// A tracker that streams nothing until told to: the configured feature reports reach the device, in order, on
// the first open and again on every re-open (a replugged device has forgotten them).
TEST_F(HidUmockdev, InitFeatureReportsAreSentInOrderOnEveryOpen) {
  TrackerConfig s = hid_settings();
  s.hid.init_feature_reports = {{0x02, 0x01}, {0x05, 0x00, 0x10, 0xFF}};
  Collector c;
  auto made = make_tracker(s, collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(eventually([&] { return t.stats().opens >= 1; }));
  EXPECT_EQ(device.feature_reports(), s.hid.init_feature_reports);
  EXPECT_EQ(t.state(), TrackerState::Opening);  // told to start; nothing streamed yet

  device.unplug();
  ASSERT_TRUE(eventually([&] { return t.state() == TrackerState::Disconnected; })) << to_string(t.state());
  ASSERT_TRUE(device.plug({})) << device.error();
  ASSERT_TRUE(eventually([&] { return t.stats().opens == 2; })) << "state " << to_string(t.state());
  const auto sent = device.feature_reports();
  ASSERT_EQ(sent.size(), 4u);
  EXPECT_EQ(sent[2], s.hid.init_feature_reports[0]);
  EXPECT_EQ(sent[3], s.hid.init_feature_reports[1]);
}

TEST(HidUmockdevRefusing, ARefusedInitReportIsOneErrorNamingItsIndexAndNoOpen) {
  if (!UmockdevTracker::available()) GTEST_SKIP() << "not under umockdev-wrapper";
  UmockdevTracker device;
  lungar::testing::UmockdevTrackerSpec spec;
  spec.refuse_feature_reports = true;
  ASSERT_TRUE(device.plug(spec)) << device.error();
  TrackerConfig s = hid_settings();
  s.hid.init_feature_reports = {{0x02, 0x01}};
  std::mutex m;
  std::vector<std::string> lines;
  TrackerOptions o;
  o.log = [&](const std::string& line) {
    std::lock_guard lock(m);
    lines.push_back(line);
  };
  auto made = make_tracker(s, o);
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(eventually([&] { return device.feature_reports().size() >= 2; }));  // refused, then tried again
  (*made)->stop();
  EXPECT_EQ((*made)->stats().opens, 0u);
  std::lock_guard lock(m);
  const auto it = std::find_if(lines.begin(), lines.end(), [](const std::string& l) {
    return l.find("init_feature_reports[0]") != std::string::npos;
  });
  ASSERT_NE(it, lines.end());
  EXPECT_NE(it->find("(2 bytes, report id 0x02) was refused by /dev/hidraw"), std::string::npos) << *it;
}

TEST(HidUmockdevAbsent, NoDeviceMatchingTheProfileIsSaidOnceWithDoctorsFixThenRetriedQuietly) {
  if (!UmockdevTracker::available()) GTEST_SKIP() << "not under umockdev-wrapper";
  UmockdevTracker device;
  lungar::testing::UmockdevTrackerSpec other;
  other.product_id = 0x9999;  // plugged in, but not the profile's
  ASSERT_TRUE(device.plug(other)) << device.error();
  std::mutex m;
  std::vector<std::string> lines;
  TrackerOptions o;
  o.log = [&](const std::string& line) {
    std::lock_guard lock(m);
    lines.push_back(line);
  };
  auto made = make_tracker(hid_settings(), o);
  ASSERT_TRUE(made) << made.error();
  // Tries at 0, 20, 60, 140 and 300 ms (the back-off doubles from 20 ms): five misses.
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  device.unplug();
  ASSERT_TRUE(device.plug({})) << device.error();  // the profile's tracker comes: the quiet retries find it
  ASSERT_TRUE(eventually([&] { return (*made)->stats().opens == 1; })) << "state " << to_string((*made)->state());
  (*made)->stop();
  std::lock_guard lock(m);
  std::vector<std::string> said;
  std::copy_if(lines.begin(), lines.end(), std::back_inserter(said),
               [](const std::string& l) { return l.find("no HID device matches") != std::string::npos; });
  ASSERT_EQ(said.size(), 1u) << "once, not on every try";
  EXPECT_NE(said[0].find("vendor_id 0x1234, product_id 0x5678"), std::string::npos) << said[0];
  EXPECT_NE(said[0].find("lungar doctor"), std::string::npos) << said[0];
}
