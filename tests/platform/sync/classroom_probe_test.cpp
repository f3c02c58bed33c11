// The classroom's DDS link between separate processes on loopback, where the test itself plays one side with
// raw DDS entities: a rogue instructor's malformed samples are dropped and counted by a trainee
// (lungar-sync-probe, a station without rendering), and a trainee never publishes shared state. The whole
// runtime's classroom (turns, breath offset, late joiner, lost and back, refusals) is classroom_runtime_test.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <regex>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "drivers/classroom/classroom_link.h"
#include "drivers/classroom/classroom_topics.h"
#include "drivers/classroom/wire.h"
#include "drivers/dds/dds.h"
#include "station_process.h"
#include "stations_test.h"
#include "sync_test_support.h"

using namespace lungar;
using namespace lungar::platform;
using namespace lungar::classroom;
using lungar::testing::StationProcess;
using lungar::testing::realtime_ns;
using lungar::testing::sleep_s;

namespace {

const std::string kProbe = std::string(LUNGAR_BINARY_DIR) + "/platform/lungar-sync-probe";

class ClassroomProbe : public lungar::testing::StationsTest {
 protected:
  ClassroomProbe() : StationsTest("room") {}
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
  std::vector<std::string> report_to(const std::string& station) const {
    return {"--report-json", (dir / (station + ".json")).string()};
  }
};

}  // namespace

TEST_F(ClassroomProbe, MalformedSamplesAreDroppedAndCounted) {
  auto trainee = start("trainee", "victim", 5, report_to("victim"));
  // A rogue instructor made by hand: a NaN pose, a negative breathing rate, a heartbeat with a NaN time.
  auto d = dds::Domain::create(static_cast<std::uint32_t>(std::stoul(domain)), lungar::testing::kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  auto pose_topic = dds::Topic<lungar_sync_PatientPose>::create(d->participant(), lungar_sync_PatientPose_desc,
                                                                classroom::TopicInfo<lungar_sync_PatientPose>::name);
  auto state_topic = dds::Topic<lungar_sync_BreathingState>::create(
      d->participant(), lungar_sync_BreathingState_desc, classroom::TopicInfo<lungar_sync_BreathingState>::name);
  dds::Qos pose_qos, state_qos;
  classroom::classroom_qos<lungar_sync_PatientPose>(pose_qos, room);
  classroom::classroom_qos<lungar_sync_BreathingState>(state_qos, room);
  auto pose_writer = dds::Writer<lungar_sync_PatientPose>::create(d->participant(), *pose_topic, pose_qos);
  auto state_writer = dds::Writer<lungar_sync_BreathingState>::create(d->participant(), *state_topic, state_qos);
  ASSERT_TRUE(pose_writer && state_writer);
  for (int i = 0; i < 100 && pose_writer->matched() < 1; ++i) sleep_s(0.02);
  ASSERT_EQ(pose_writer->matched(), 1);
  lungar_sync_PatientPose pose{};
  pose.session = 5;
  pose.orientation_wxyz.w = std::nan("");
  pose.measured_ns = realtime_ns();
  lungar_sync_BreathingState state{};
  state.session = 5;
  state.rate_bpm = -12.0;
  state.ie_ratio = 0.5;
  state.tidal_volume_ml = 500;
  state.ventilator_tau_s = 0.5;
  state.time_base_ns = realtime_ns();
  ASSERT_TRUE(state_writer->write(state, realtime_ns()));
  for (int i = 0; i < 20; ++i) {  // best effort, keep-last 1: not every one need arrive, one must
    ASSERT_TRUE(pose_writer->write(pose, realtime_ns()));
    sleep_s(0.05);
  }
  ASSERT_EQ(trainee->wait(20), 0) << trainee->err();
  const auto r = json_of("victim");
  EXPECT_GE(r["sync_malformed"].get<int>(), 2) << r.dump();  // the state, and at least one pose
  EXPECT_EQ(r["sync_poses"], 0);  // never applied
  EXPECT_EQ(r["sync_state"], "lost");
  EXPECT_EQ(r["sync_instructor"], "");
  EXPECT_NE(trainee->err().find("lungar_breathing_state: rate_bpm: expected [2, 60]"), std::string::npos)
      << trainee->err();
  EXPECT_NE(trainee->err().find("lungar_patient_pose: orientation_wxyz: expected a finite number"), std::string::npos)
      << trainee->err();
}

TEST_F(ClassroomProbe, AStationNameOfMoreThan63CharactersIsRefusedAtOpen) {
  // The Station topic carries the name in 64 bytes with its terminating zero: 63 characters open, 64 are refused
  // before any DDS entity is made, naming the setting.
  classroom::SyncOptions o;
  o.classroom = room;
  o.domain = static_cast<std::uint32_t>(std::stoul(domain));
  o.cyclonedds_xml = lungar::testing::kLoopbackXml;
  o.log = [](const std::string&) {};
  o.station = std::string(63, 's');
  auto fits = classroom::ClassroomLink::open(o, classroom::kWireTrainee);
  ASSERT_TRUE(fits) << fits.error();
  o.station = std::string(64, 's');
  auto long_name = classroom::ClassroomLink::open(o, classroom::kWireTrainee);
  ASSERT_FALSE(long_name);
  EXPECT_NE(long_name.error().find("sync.station: expected at most 63 characters"), std::string::npos)
      << long_name.error();
}

TEST_F(ClassroomProbe, MalformedSamplesAreLoggedTheFirstFiveThenEveryHundredth) {
  // A rogue stream of malformed samples must not flood the log: each is counted, the first five are logged, then
  // one in a hundred, with the count so far.
  std::vector<std::string> lines;
  classroom::SyncOptions o;
  o.classroom = room;
  o.domain = static_cast<std::uint32_t>(std::stoul(domain));
  o.cyclonedds_xml = lungar::testing::kLoopbackXml;
  o.station = "logged";
  o.log = [&](const std::string& line) { lines.push_back(line); };
  auto link = classroom::ClassroomLink::open(o, classroom::kWireTrainee);
  ASSERT_TRUE(link) << link.error();
  lines.clear();
  for (int i = 0; i < 250; ++i) (*link)->malformed("rate_bpm: expected [2, 60]");
  EXPECT_EQ((*link)->malformed_count(), 250u);
  std::vector<int> logged;
  const std::regex so_far(R"(\((\d+) so far\))");
  for (const std::string& line : lines) {
    std::smatch m;
    if (std::regex_search(line, m, so_far)) logged.push_back(std::stoi(m[1]));
  }
  EXPECT_EQ(logged, (std::vector<int>{1, 2, 3, 4, 5, 100, 200}));
}

TEST_F(ClassroomProbe, ATraineeNeverPublishesSharedState) {
  auto d = dds::Domain::create(static_cast<std::uint32_t>(std::stoul(domain)), lungar::testing::kLoopbackXml);
  ASSERT_TRUE(d) << d.error();
  auto reader_of = [&](auto tag) {
    using T = decltype(tag);
    auto t =
        dds::Topic<T>::create(d->participant(), classroom::TopicInfo<T>::descriptor(), classroom::TopicInfo<T>::name);
    dds::Qos q;
    classroom::classroom_qos<T>(q, room);
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
