// The OpenIGTLink source against a real server on loopback: a test server written with libopenigtlink's message
// classes (as PlusServer and Slicer are) on a port the OS picks. Poses arrive equal to what was sent, at the sent
// rate; the server going away and coming back goes disconnected -> streaming without a restart; malformed
// messages are counted by reason and never applied; a recording replays to bit-identical poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <unistd.h>

#include "drivers/igtl/igtl_decoder.h"
#include "drivers/igtl/igtl_messages.h"
#include "drivers/igtl/tcp_socket.h"
#include "drivers/tracker_factory/tracker_factory.h"
#include "drivers/trk/trk_reader.h"
#include "tracker_test_support.h"

using namespace lungar;
using namespace lungar::drivers;
using namespace lungar::testing;

namespace {

/// A one-client OpenIGTLink server on 127.0.0.1; port 0 = one the OS picks.
struct TestServer {
  TcpListener listener;
  std::optional<TcpSocket> client;
  explicit TestServer(int port = 0) {
    auto l = TcpListener::listen("127.0.0.1", port);
    EXPECT_TRUE(l) << l.error();
    if (l) listener = l.take();
  }
  bool wait_for_client(double seconds = 10.0) {
    return eventually([&] { return (client = listener.accept(10)).has_value(); }, seconds);
  }
  bool send(const std::vector<std::uint8_t>& bytes) { return client && client->write_all(bytes); }
  void stop() {
    client.reset();
    listener.close();
  }
};

TrackerConfig igtl_settings(int port) {
  TrackerConfig t;
  t.source = TrackerSource::Igtl;
  t.igtl.host = "127.0.0.1";
  t.igtl.port = port;
  t.reopen_backoff_ms = 20;  // tests wait for reconnects; keep the back-off short
  t.stale_ms = 100;
  return t;
}

Eigen::Matrix4d pose_at(double t_s, double phase) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(0.5 * std::sin(t_s + phase), Eigen::Vector3d(1, 0.5 * phase, 0.2).normalized())
          .toRotationMatrix();
  m.topRightCorner<3, 1>() = Eigen::Vector3d(100 * std::cos(t_s) + 0.123456, -700 + phase, 1000 + 10 * t_s);
  return m;
}

/// Position and quaternion as they are on the wire (float), for the 1e-6 comparison.
void expect_sent(const PoseSample& got, const Eigen::Matrix4d& sent) {
  const Eigen::Matrix4d f = sent.cast<float>().cast<double>();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got.position_mm[i], f(i, 3), 1e-6);
  EXPECT_LT(got.orientation().angularDistance(Eigen::Quaterniond(Eigen::Matrix3d(f.topLeftCorner<3, 3>()))), 1e-6);
}

std::uint64_t unix_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

}  // namespace

TEST(IgtlSource, TwoDevicesAt60HzArriveAsSentAtTheSentRate) {
  TestServer server;
  Collector c;
  auto made = make_tracker(igtl_settings(server.listener.port()), collecting(c));
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(server.wait_for_client());
  const int n = 120;  // 2 s at 60 Hz, two devices per tick
  std::vector<std::int64_t> sent_ns(n);
  std::vector<Eigen::Matrix4d> head(n), patient(n);
  auto next = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    head[k] = pose_at(k / 60.0, 0.0);
    patient[k] = pose_at(k / 60.0, 1.0);
    const IgtlTime time = IgtlTime::from_ns(unix_ns());
    sent_ns[k] = monotonic_ns();
    ASSERT_TRUE(server.send(igtl_transform_message("HeadToTracker", head[k], time)));
    ASSERT_TRUE(server.send(igtl_transform_message("PatientToTracker", patient[k], time)));
    next += std::chrono::microseconds(16667);
    std::this_thread::sleep_until(next);
  }
  ASSERT_TRUE(eventually([&] { return c.size() == 2u * n; })) << c.size();
  const auto s = c.copy();
  std::vector<double> age_ms;
  for (int k = 0; k < n; ++k) {
    SCOPED_TRACE(k);
    ASSERT_EQ(s[2 * k].role, Role::Head);
    ASSERT_EQ(s[2 * k + 1].role, Role::Patient);
    expect_sent(s[2 * k], head[k]);
    expect_sent(s[2 * k + 1], patient[k]);
    EXPECT_EQ(s[2 * k].t_device_ns, s[2 * k + 1].t_device_ns);  // one timestamp per tick
    age_ms.push_back((s[2 * k + 1].t_arrival_ns - sent_ns[k]) * 1e-6);
  }
  const double span_s = (s.back().t_arrival_ns - s[1].t_arrival_ns) * 1e-9;
  const double rate_hz = (n - 1) / span_s;
  std::sort(age_ms.begin(), age_ms.end());
  std::printf(
      "[ MEASURED ] igtl on loopback: %d ticks of 2 TRANSFORMs, patient rate %.2f Hz, send -> pose p50 %.3f ms, "
      "p99 %.3f ms, max %.3f ms\n",
      n, rate_hz, age_ms[age_ms.size() / 2], age_ms[age_ms.size() * 99 / 100], age_ms.back());
  // Generous on purpose (a loaded 2-core machine delays the sender's sleeps, never the count): 60 Hz +-25 %.
  EXPECT_NEAR(rate_hz, 60.0, 15.0);
  const TrackerStats st = (*made)->stats();
  EXPECT_EQ(st.accepted, 2u * n);
  EXPECT_EQ(st.malformed, 0u);
  EXPECT_EQ(st.opens, 1u);
  EXPECT_EQ((*made)->state(), TrackerState::Streaming);
}

TEST(IgtlSource, ServerStopAndRestartGoesDisconnectedThenStreamingWithoutARestart) {
  auto server = std::make_unique<TestServer>();
  const int port = server->listener.port();
  Collector c;
  auto made = make_tracker(igtl_settings(port), collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(server->wait_for_client());
  ASSERT_TRUE(server->send(igtl_transform_message("PatientToTracker", pose_at(0, 1), {})));
  ASSERT_TRUE(eventually([&] { return c.size() == 1; }));
  EXPECT_EQ(t.state(), TrackerState::Streaming);
  ASSERT_TRUE(eventually([&] { return t.state() == TrackerState::Stale; }));  // silent for stale_ms, still connected
  EXPECT_EQ(t.stats().reconnects, 0u);

  server->stop();  // PlusServer quits
  ASSERT_TRUE(eventually([&] { return t.state() == TrackerState::Disconnected; })) << to_string(t.state());
  const PoseSample kept = t.latest(Role::Patient, monotonic_ns());
  EXPECT_TRUE(kept.valid());
  EXPECT_TRUE(kept.stale());  // the picture keeps the last pose, marked stale

  server = std::make_unique<TestServer>(port);  // and starts again on the same port
  ASSERT_TRUE(server->wait_for_client());
  ASSERT_TRUE(server->send(igtl_transform_message("PatientToTracker", pose_at(1, 1), {})));
  ASSERT_TRUE(eventually([&] { return c.size() == 2; }));
  EXPECT_EQ(t.state(), TrackerState::Streaming);
  const PoseSample fresh = t.latest(Role::Patient, monotonic_ns());
  EXPECT_FALSE(fresh.stale());
  expect_sent(fresh, pose_at(1, 1));
  EXPECT_EQ(t.stats().reconnects, 1u);
  EXPECT_EQ(t.stats().opens, 2u);
}

TEST(IgtlSource, MalformedMessagesAreCountedByReasonAndNeverApplied) {
  TestServer server;
  Collector c;
  auto made = make_tracker(igtl_settings(server.listener.port()), collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(server.wait_for_client());
  const Eigen::Matrix4d good = pose_at(0.5, 1);
  ASSERT_TRUE(server.send(igtl_transform_message("PatientToTracker", good, {})));
  ASSERT_TRUE(server.send(igtl_status_message("Server", {})));  // unknown type: its body is skipped unread
  auto crc = igtl_transform_message("PatientToTracker", pose_at(2, 1), {});
  crc.back() ^= 0x40;
  ASSERT_TRUE(server.send(crc));
  Eigen::Matrix4d sheared = pose_at(3, 1);
  sheared(0, 1) += 0.3;
  ASSERT_TRUE(server.send(igtl_transform_message("PatientToTracker", sheared, {})));
  ASSERT_TRUE(server.send(igtl_transform_message("ProbeToTracker", pose_at(4, 1), {})));  // feeds no role
  // A truncated body: the sender dies in the middle of a message.
  const auto cut = igtl_transform_message("PatientToTracker", pose_at(5, 1), {});
  ASSERT_TRUE(server.send(std::vector<std::uint8_t>(cut.begin(), cut.begin() + kIgtlHeaderBytes + 20)));
  server.client.reset();
  ASSERT_TRUE(eventually([&] { return t.stats().reports == 6; })) << t.stats().reports;
  const TrackerStats s = t.stats();
  EXPECT_EQ(s.accepted, 1u);
  EXPECT_EQ(s.ignored, 1u);
  EXPECT_EQ(s.malformed, 4u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::UnknownType)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::BadCrc)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::NotRigid)], 1u);
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::Truncated)], 1u);
  ASSERT_EQ(c.size(), 1u);
  expect_sent(t.latest(Role::Patient, monotonic_ns()), good);  // the last good pose, untouched
  // The stream is still usable after every one of them: the next client's first pose is taken.
  ASSERT_TRUE(server.wait_for_client());
  ASSERT_TRUE(server.send(igtl_transform_message("PatientToTracker", pose_at(6, 1), {})));
  ASSERT_TRUE(eventually([&] { return c.size() == 2; }));
}

// A known type whose header announces a body too short for it: the body is read with the header and the whole
// refused for its length (not the header alone, as an unknown type's), and the stream goes on.
TEST(IgtlSource, AKnownTypeWithATooShortBodyIsReadWholeAndRefusedForItsLength) {
  TestServer server;
  Collector c;
  auto made = make_tracker(igtl_settings(server.listener.port()), collecting(c));
  ASSERT_TRUE(made) << made.error();
  Tracker& t = **made;
  ASSERT_TRUE(server.wait_for_client());
  std::vector<std::uint8_t> short_one = igtl_transform_message("PatientToTracker", pose_at(1, 1), {});
  short_one.resize(kIgtlHeaderBytes + 1);
  for (int k = 0; k < 8; ++k) short_one[42 + k] = k == 7 ? 1 : 0;  // the header's body_size (big-endian): 1 byte
  ASSERT_TRUE(server.send(short_one));
  ASSERT_TRUE(server.send(igtl_transform_message("PatientToTracker", pose_at(2, 1), {})));
  ASSERT_TRUE(eventually([&] { return t.stats().reports == 2; })) << t.stats().reports;
  const TrackerStats s = t.stats();
  EXPECT_EQ(s.malformed_by_reason[static_cast<int>(DecodeError::WrongLength)], 1u);
  EXPECT_EQ(s.accepted, 1u);
}

TEST(IgtlSource, ARecordingReplaysToBitIdenticalPoses) {
  const auto dir = std::filesystem::temp_directory_path() / ("lungar_igtl_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string rec = (dir / "igtl.trk").string();
  TestServer server;
  Collector live;
  TrackerOptions o = collecting(live);
  o.record_path = rec;
  auto made = make_tracker(igtl_settings(server.listener.port()), o);
  ASSERT_TRUE(made) << made.error();
  ASSERT_TRUE(server.wait_for_client());
  const std::vector<IgtlTool> tools = {{"HeadToTracker", pose_at(0.1, 0)}, {"PatientToTracker", pose_at(0.1, 1)}};
  for (int k = 0; k < 30; ++k) {
    const IgtlTime time = IgtlTime::from_ns(1'700'000'000'000'000'000ull + k * 16'666'667ull);
    ASSERT_TRUE(server.send(igtl_transform_message("PatientToTracker", pose_at(k * 0.1, 1), time)));
    ASSERT_TRUE(server.send(k % 2 ? igtl_tdata_message("T", tools, time) : igtl_qtdata_message("T", tools, time)));
  }
  ASSERT_TRUE(server.send(igtl_status_message("Server", {})));
  ASSERT_TRUE(eventually([&] { return (*made)->stats().reports == 61; }));
  (*made)->stop();

  const auto a = live.copy();
  ASSERT_EQ(a.size(), 90u);
  expect_bit_identical(a, replay_all(rec));
  const auto log = load_trk(rec);  // every message whole, the STATUS one too, each marked as OpenIGTLink
  ASSERT_TRUE(log) << log.error();
  ASSERT_EQ(log->records.size(), 61u);
  for (const auto& r : log->records) EXPECT_EQ(r.source, TrkSource::Igtl);
  std::filesystem::remove_all(dir);
}
