// The classroom's DDS link between separate processes on loopback (lungar-sync-probe: stations without
// rendering): a skewed clock estimated, a late joiner in step at once, an instructor killed and restarted, a
// second instructor refused, two classrooms apart, malformed samples dropped, a trainee that never publishes.
// Tolerances are the issue's: in step within 100 ms of joining, breath offset p99 <= 5 ms, lost within 500 ms.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "platform/sync/classroom_topics.h"
#include "platform/sync/dds.h"
#include "platform/sync/wire.h"
#include "station_process.h"
#include "sync_test_support.h"

using namespace lungar;
using namespace lungar::platform;
using lungar::testing::StationProcess;

namespace {

const std::string kProbe = std::string(LUNGAR_BINARY_DIR) + "/platform/lungar-sync-probe";

std::int64_t realtime_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

void sleep_s(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

class ClassroomProbe : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = lungar::testing::test_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    domain = std::to_string(lungar::testing::test_domain());
    room = lungar::testing::test_classroom("room");
  }
  std::vector<std::string> args(const std::string& role, const std::string& station, double seconds,
                                const std::string& classroom) const {
    return {"--role", role, "--station", station, "--seconds", std::to_string(seconds), "--domain", domain,
            "--classroom", classroom, "--cyclonedds-xml", lungar::testing::kLoopbackXml};
  }
  std::unique_ptr<StationProcess> start(const std::string& role, const std::string& station, double seconds,
                                        std::vector<std::string> extra = {}, std::string classroom = "") {
    auto a = args(role, station, seconds, classroom.empty() ? room : classroom);
    a.insert(a.end(), extra.begin(), extra.end());
    return std::make_unique<StationProcess>(kProbe, a, dir / station);
  }
  nlohmann::json report(const std::string& station) const {
    std::ifstream in(dir / (station + ".json"));
    return nlohmann::json::parse(in);
  }
  std::vector<std::string> report_to(const std::string& station) const {
    return {"--report-json", (dir / (station + ".json")).string()};
  }

  std::filesystem::path dir;
  std::string domain, room;
};

}  // namespace

TEST_F(ClassroomProbe, SkewedClockLateJoinerLostAndBack) {
  auto instructor = start("instructor", "inst", 30);
  auto skewed = start("trainee", "skewed", 10.5, [&] {
    auto e = report_to("skewed");
    e.insert(e.end(), {"--clock-skew-ms", "250"});
    return e;
  }());
  sleep_s(3.0);
  auto late = start("trainee", "late", 7.5, report_to("late"));
  sleep_s(2.5);
  const std::int64_t killed_ns = realtime_ns();
  instructor->kill_now();
  sleep_s(1.5);
  auto again = start("instructor", "inst-again", 8);
  ASSERT_EQ(skewed->wait(30), 0) << skewed->err();
  ASSERT_EQ(late->wait(30), 0) << late->err();

  const auto s = report("skewed");
  // The estimate finds the skew (its error is at most half the round trip, well under a millisecond here).
  EXPECT_NEAR(s["sync_clock_offset_ms"].get<double>(), -250.0, 2.0) << s.dump();
  EXPECT_LE(s["sync_breath_offset_ms_p99"].get<double>(), 5.0) << s.dump();
  EXPECT_EQ(s["sync_malformed"], 0);
  const auto l = report("late");
  EXPECT_GE(l["sync_join_to_in_sync_ms"].get<double>(), 0.0) << l.dump();
  for (const auto& r : {s, l}) {
    // in_sync, then lost within 500 ms of the kill, then in_sync again with the restarted instructor.
    const auto& tr = r["sync_transitions"];
    std::int64_t lost_ns = 0, back_ns = 0;
    for (const auto& t : tr) {
      if (t["state"] == "lost" && t["realtime_ns"].get<std::int64_t>() > killed_ns && lost_ns == 0) {
        lost_ns = t["realtime_ns"].get<std::int64_t>();
      }
      if (t["state"] == "in_sync" && lost_ns != 0) back_ns = t["realtime_ns"].get<std::int64_t>();
    }
    ASSERT_NE(lost_ns, 0) << r.dump();
    EXPECT_LE((lost_ns - killed_ns) * 1e-6, 500.0) << r.dump();
    EXPECT_GT(back_ns, lost_ns) << r.dump();
    EXPECT_EQ(r["sync_state"], "in_sync");
    EXPECT_EQ(r["sync_instructor"], "inst-again");
    EXPECT_GT(r["sync_poses"].get<int>(), 100);
  }
  // The late trainee joined a running instructor: in step within 100 ms of its first word... measured on its
  // first join, before the restart; its log has the line.
  const std::string log = late->err();
  const auto at = log.find("sync: in step with instructor 'inst' ");
  ASSERT_NE(at, std::string::npos) << log;
  const double join_ms = std::stod(log.substr(at + std::string("sync: in step with instructor 'inst' ").size()));
  EXPECT_LE(join_ms, 100.0) << log;
  again->kill_now();
}

TEST_F(ClassroomProbe, ASecondInstructorIsRefusedAndAnotherClassroomIsApart) {
  auto first = start("instructor", "first", 8);
  sleep_s(1.0);
  auto second = start("instructor", "second", 3);
  EXPECT_EQ(second->wait(10), 1);
  const std::string err = second->err();
  EXPECT_NE(err.find("already has an instructor: station 'first'"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;  // one line
  // The same domain, another classroom: an instructor of its own, and a trainee that follows it alone.
  const std::string other = lungar::testing::test_classroom("other-room");
  auto other_instructor = start("instructor", "other-inst", 6, {}, other);
  auto trainee = start("trainee", "other-trainee", 3, report_to("other-trainee"), other);
  ASSERT_EQ(trainee->wait(20), 0) << trainee->err();
  EXPECT_EQ(other_instructor->wait(20), 0) << other_instructor->err();
  const auto r = report("other-trainee");
  EXPECT_EQ(r["sync_instructor"], "other-inst");
  EXPECT_EQ(r["sync_state"], "in_sync");
  EXPECT_EQ(r["sync_peers"], 1) << r.dump();  // other-inst only: 'first' is in another classroom
  EXPECT_EQ(first->wait(20), 0) << first->err();
}

TEST_F(ClassroomProbe, MalformedSamplesAreDroppedAndCounted) {
  auto trainee = start("trainee", "victim", 3, report_to("victim"));
  // A rogue instructor made by hand: a NaN pose, a negative breathing rate, a heartbeat with a NaN time.
  auto d = dds::Domain::create(static_cast<std::uint32_t>(std::stoul(domain)), lungar::testing::kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  auto pose_topic = dds::Topic<lungar_sync_PatientPose>::create(d->participant(), lungar_sync_PatientPose_desc,
                                                                sync::TopicInfo<lungar_sync_PatientPose>::name);
  auto state_topic = dds::Topic<lungar_sync_BreathingState>::create(
      d->participant(), lungar_sync_BreathingState_desc, sync::TopicInfo<lungar_sync_BreathingState>::name);
  dds::Qos pose_qos, state_qos;
  sync::classroom_qos<lungar_sync_PatientPose>(pose_qos, room);
  sync::classroom_qos<lungar_sync_BreathingState>(state_qos, room);
  auto pose_writer = dds::Writer<lungar_sync_PatientPose>::create(d->participant(), *pose_topic, pose_qos);
  auto state_writer = dds::Writer<lungar_sync_BreathingState>::create(d->participant(), *state_topic, state_qos);
  ASSERT_TRUE(pose_writer && state_writer);
  for (int i = 0; i < 100 && pose_writer->matched() < 1; ++i) sleep_s(0.02);
  ASSERT_EQ(pose_writer->matched(), 1);
  lungar_sync_PatientPose pose{};
  pose.session = 5;
  pose.orientation_wxyz[0] = std::nan("");
  pose.measured_ns = realtime_ns();
  lungar_sync_BreathingState state{};
  state.session = 5;
  state.rate_bpm = -12.0;
  state.ie_ratio = 0.5;
  state.tidal_volume_ml = 500;
  state.ventilator_tau_s = 0.5;
  state.time_base_ns = realtime_ns();
  ASSERT_TRUE(state_writer->write(state, realtime_ns()));
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(pose_writer->write(pose, realtime_ns()));
    sleep_s(0.05);
  }
  ASSERT_EQ(trainee->wait(20), 0) << trainee->err();
  const auto r = report("victim");
  EXPECT_GE(r["sync_malformed"].get<int>(), 6) << r.dump();
  EXPECT_EQ(r["sync_poses"], 0);  // never applied
  EXPECT_EQ(r["sync_state"], "lost");
  EXPECT_EQ(r["sync_instructor"], "");
  EXPECT_NE(trainee->err().find("rate_bpm: expected [2, 60]"), std::string::npos) << trainee->err();
}

TEST_F(ClassroomProbe, ATraineeNeverPublishesSharedState) {
  auto d = dds::Domain::create(static_cast<std::uint32_t>(std::stoul(domain)), lungar::testing::kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  auto reader_of = [&](auto tag) {
    using T = decltype(tag);
    auto t = dds::Topic<T>::create(d->participant(), sync::TopicInfo<T>::descriptor(), sync::TopicInfo<T>::name);
    dds::Qos q;
    sync::classroom_qos<T>(q, room);
    auto r = dds::Reader<T>::create(d->participant(), *t, q);
    EXPECT_TRUE(r) << r.error();
    return std::make_pair(t.take(), r.take());
  };
  auto station = reader_of(lungar_sync_Station{});
  auto pose = reader_of(lungar_sync_PatientPose{});
  auto state = reader_of(lungar_sync_BreathingState{});
  auto events = reader_of(lungar_sync_ScenarioEvents{});
  auto heartbeat = reader_of(lungar_sync_Heartbeat{});
  auto reply = reader_of(lungar_sync_TimeReply{});
  auto trainee = start("trainee", "quiet", 2);
  for (int i = 0; i < 100 && station.second.matched() < 1; ++i) sleep_s(0.02);
  ASSERT_EQ(station.second.matched(), 1);  // discovery worked: its Station writer is there
  sleep_s(0.3);
  EXPECT_EQ(pose.second.matched(), 0);
  EXPECT_EQ(state.second.matched(), 0);
  EXPECT_EQ(events.second.matched(), 0);
  EXPECT_EQ(heartbeat.second.matched(), 0);
  EXPECT_EQ(reply.second.matched(), 0);
  EXPECT_EQ(trainee->wait(10), 0) << trainee->err();
}
