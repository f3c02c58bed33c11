// Checked conversions of the classroom's samples: round trips, and every malformed or out-of-range sample
// refused with a line naming the topic and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "drivers/classroom/wire.h"

using namespace lungar;
using namespace lungar::classroom;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

lungar_sync_PatientPose good_pose() {
  SharedPose p{{10.0, 700.0, -20.0}, {std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0}, 1'700'000'000'000'000'000};
  lungar_sync_PatientPose w{};
  to_wire(p, 77, 3, w);
  return w;
}

lungar_sync_BreathingState good_state() {
  lungar_sync_BreathingState s{};
  sim::BreathingParams p;
  p.preset = sim::Preset::Fibrosis;
  p.rate_bpm = 18.0;
  p.tidal_volume_ml = 400.0;
  to_wire(p, s);
  s.time_base_ns = 1'700'000'000'000'000'000;
  return s;
}
}  // namespace

TEST(SyncWire, APoseRoundTrips) {
  const lungar_sync_PatientPose w = good_pose();
  EXPECT_EQ(w.session, 77u);
  EXPECT_EQ(w.seq, 3u);
  auto back = from_wire(w);
  ASSERT_TRUE(back) << back.error();
  EXPECT_DOUBLE_EQ(back->position_mm[1], 700.0);
  EXPECT_DOUBLE_EQ(back->orientation_wxyz[1], std::sqrt(0.5));
  EXPECT_EQ(back->measured_ns, 1'700'000'000'000'000'000);
}

TEST(SyncWire, ANaNPoseIsRefusedNamingTheField) {
  lungar_sync_PatientPose w = good_pose();
  w.orientation_wxyz.y = kNaN;
  auto r = from_wire(w);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("lungar_patient_pose: orientation_wxyz"), std::string::npos) << r.error();
  w = good_pose();
  w.position_mm.x = kNaN;
  r = from_wire(w);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("position_mm[0]"), std::string::npos) << r.error();
}

TEST(SyncWire, OutOfRangePosesAreRefused) {
  lungar_sync_PatientPose w = good_pose();
  w.position_mm.z = 2e5;  // 200 m away
  EXPECT_FALSE(from_wire(w));
  w = good_pose();
  w.orientation_wxyz.w = 0.9;  // not a unit quaternion
  auto r = from_wire(w);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("unit quaternion"), std::string::npos) << r.error();
  w = good_pose();
  w.measured_ns = -5;
  EXPECT_FALSE(from_wire(w));
}

TEST(SyncWire, BreathingStateRoundTripsAndANegativeRateIsRefused) {
  lungar_sync_BreathingState s = good_state();
  auto p = from_wire(s);
  ASSERT_TRUE(p) << p.error();
  EXPECT_EQ(p->preset, sim::Preset::Fibrosis);
  EXPECT_DOUBLE_EQ(p->rate_bpm, 18.0);
  EXPECT_DOUBLE_EQ(p->tidal_volume_ml, 400.0);
  s.rate_bpm = -12.0;
  auto r = from_wire(s);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("lungar_breathing_state: rate_bpm"), std::string::npos) << r.error();
  s = good_state();
  s.preset = 9;
  EXPECT_FALSE(from_wire(s));
  s = good_state();
  s.mode = 2;
  EXPECT_FALSE(from_wire(s));
  s = good_state();
  s.tidal_volume_ml = kNaN;
  EXPECT_FALSE(from_wire(s));
  s = good_state();
  s.time_base_ns = 0;
  EXPECT_FALSE(from_wire(s));
}

TEST(SyncWire, ScenarioEventsRoundTrip) {
  sim::PatternChange change;
  change.rate_bpm = 20.0;
  change.preset = sim::Preset::Emphysema;
  const std::vector<sim::Event> events = {sim::Event::set(5.0, change, 3.0), sim::Event::sigh(8.0, 900.0),
                                          sim::Event::of(10.0, sim::EventKind::HoldStart)};
  std::vector<lungar_sync_ScenarioEvent> storage;
  lungar_sync_ScenarioEvents w{};
  ASSERT_TRUE(to_wire(events, storage, w));
  ASSERT_EQ(w.events._length, 3u);
  auto back = from_wire(w);
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->size(), 3u);
  EXPECT_EQ((*back)[0].kind, sim::EventKind::Change);
  EXPECT_EQ((*back)[0].change.rate_bpm, 20.0);
  EXPECT_EQ((*back)[0].change.preset, sim::Preset::Emphysema);
  EXPECT_FALSE((*back)[0].change.tidal_volume_ml.has_value());  // not set stays not set
  EXPECT_DOUBLE_EQ((*back)[0].transition_s, 3.0);
  EXPECT_EQ((*back)[1].kind, sim::EventKind::Sigh);
  EXPECT_DOUBLE_EQ((*back)[1].sigh_volume_ml, 900.0);
  EXPECT_EQ((*back)[2].kind, sim::EventKind::HoldStart);
}

TEST(SyncWire, AChangeOfEveryBreathingSettingRoundTrips) {
  // Each setting a change can carry has its bit in `set`: every one of them, set together, comes back as it went.
  sim::PatternChange change;
  change.preset = sim::Preset::Fibrosis;
  change.rate_bpm = 16.0;
  change.ie_ratio = 0.4;
  change.tidal_volume_ml = 450.0;
  change.mode = sim::Mode::Ventilator;
  change.ventilator_tau_s = 0.8;
  change.peep_cmh2o = 6.0;
  std::vector<lungar_sync_ScenarioEvent> storage;
  lungar_sync_ScenarioEvents w{};
  ASSERT_TRUE(to_wire(std::vector<sim::Event>{sim::Event::set(5.0, change)}, storage, w));
  auto back = from_wire(w);
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->size(), 1u);
  const sim::PatternChange& c = (*back)[0].change;
  EXPECT_EQ(c.preset, change.preset);
  EXPECT_EQ(c.rate_bpm, change.rate_bpm);
  EXPECT_EQ(c.ie_ratio, change.ie_ratio);
  EXPECT_EQ(c.tidal_volume_ml, change.tidal_volume_ml);
  EXPECT_EQ(c.mode, change.mode);
  EXPECT_EQ(c.ventilator_tau_s, change.ventilator_tau_s);
  EXPECT_EQ(c.peep_cmh2o, change.peep_cmh2o);
}

TEST(SyncWire, TheLungsPathologiesRoundTripWithTheScenarioEvents) {
  const sim::PathologyTimeline lungs{{"ards:0.6", "emphysema:0.3:left"},
                                     {{10.0, 15.0, "pneumothorax:right:40:tension", ""},
                                      {40.0, 20.0, "", "pneumothorax:right:40:tension"}}};
  std::vector<lungar_sync_PathologyEvent> storage;
  lungar_sync_ScenarioEvents w{};
  ASSERT_TRUE(to_wire(lungs, storage, w));
  EXPECT_STREQ(w.pathologies, "ards:0.6,emphysema:0.3:left");
  ASSERT_EQ(w.pathology_events._length, 2u);
  auto back = pathologies_from_wire(w);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(*back, lungs);
  lungar_sync_ScenarioEvents healthy{};
  auto none = pathologies_from_wire(healthy);
  ASSERT_TRUE(none) << none.error();
  EXPECT_TRUE(none->empty()) << "an empty list is healthy lungs";
}

TEST(SyncWire, MalformedPathologiesAreRefusedNamingWhatIsWrong) {
  const sim::PathologyTimeline lungs{{"ards:0.6"}, {{10.0, 15.0, "pneumothorax:right:40", ""}}};
  std::vector<lungar_sync_PathologyEvent> storage;
  lungar_sync_ScenarioEvents w{};
  ASSERT_TRUE(to_wire(lungs, storage, w));
  const auto refused = [&](const char* why) {
    auto r = pathologies_from_wire(w);
    ASSERT_FALSE(r) << why;
    EXPECT_NE(r.error().find("lungar_scenario_events: "), std::string::npos) << r.error();
    EXPECT_NE(r.error().find(why), std::string::npos) << r.error();
  };
  std::strcpy(w.pathologies, "ards:0.6,,asthma");
  refused("pathology at the start");
  std::strcpy(w.pathologies, "ards:0.6");
  storage[0].over_s = kNaN;
  refused("pathology event 1: over_s");
  storage[0].over_s = 15.0;
  storage[0].t_s = -1.0;
  refused("pathology event 1: at_s");
  storage[0].t_s = 10.0;
  std::strcpy(storage[0].remove, "ards:0.6");
  EXPECT_TRUE(pathologies_from_wire(w)) << "both: one pathology becomes another (a console's change of severity)";
  storage[0].add[0] = '\0';
  storage[0].remove[0] = '\0';
  refused("expected add, remove, or both");
  std::strcpy(storage[0].remove, "pneumothorax:left:20");
  refused("is not present then");
  EXPECT_TRUE(pathologies_from_wire(w).error().find("pneumothorax:left:20") != std::string::npos);

  sim::PathologyTimeline too_many{{}, std::vector<sim::PathologyEvent>(kMaxPathologyEvents + 1,
                                                                       {1.0, 1.0, "emphysema:0.1", ""})};
  EXPECT_FALSE(to_wire(too_many, storage, w)) << "more than a sample carries";
  sim::PathologyTimeline too_long{{std::string(600, 'a')}, {}};
  EXPECT_FALSE(to_wire(too_long, storage, w)) << "a list longer than a sample carries";
  // A pathology's text has 64 bytes with its terminator: the refusal says how many characters fit.
  sim::PathologyTimeline long_event{{}, {{1.0, 1.0, "emphysema:0.1:" + std::string(60, 'l'), ""}}};
  const Status s = to_wire(long_event, storage, w);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("is longer than a classroom carries (63 characters)"), std::string::npos) << s.error();
}

TEST(SyncWire, TheConsolesVentilationMapRoundTripsAndAnUnknownValueIsRefused) {
  lungar_sync_ScenarioEvents w{};
  auto own = ventilation_map_from_wire(w);
  ASSERT_TRUE(own) << own.error();
  EXPECT_FALSE(own->has_value()) << "a sample that says nothing leaves each station its own choice";
  for (const bool on : {true, false}) {
    ventilation_map_to_wire(on, w);
    auto back = ventilation_map_from_wire(w);
    ASSERT_TRUE(back) << back.error();
    EXPECT_EQ(*back, std::optional<bool>(on));
  }
  w.ventilation_map = 7;
  auto bad = ventilation_map_from_wire(w);
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error(),
            "lungar_scenario_events: ventilation_map: expected 0 (each station's own), 1 (off) or 2 (on), got 7");
}

TEST(SyncWire, MalformedScenarioEventsAreRefused) {
  const std::vector<sim::Event> events = {sim::Event::sigh(8.0), sim::Event::sigh(9.0)};
  std::vector<lungar_sync_ScenarioEvent> storage;
  lungar_sync_ScenarioEvents w{};
  ASSERT_TRUE(to_wire(events, storage, w));
  storage[1].t_s = 2.0;  // before the first
  auto r = from_wire(w);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().find("events[1]: t_s"), std::string::npos) << r.error();
  storage[1].t_s = 9.0;
  storage[1].kind = 6;
  EXPECT_FALSE(from_wire(w));
  storage[1].kind = 0;
  storage[1].set = 1u << 9;
  EXPECT_FALSE(from_wire(w));
  storage[1].set = 1u << 1;
  storage[1].rate_bpm = kNaN;
  EXPECT_FALSE(from_wire(w));
  const std::vector<sim::Event> too_many(kMaxScenarioEvents + 1, sim::Event::sigh(1.0));
  EXPECT_FALSE(to_wire(too_many, storage, w));
}

TEST(SyncWire, AFollowedBreathsDvIsCheckedOnlyWhenTheHeartbeatCarriesOne) {
  lungar_sync_Heartbeat hb{};
  hb.session = 1;
  hb.frame_ns = 1'700'000'000'000'000'000;
  hb.breath_t_s = 3.5;
  hb.dv_ml = std::nan("");  // not followed: the model's breath, its dV not carried
  EXPECT_TRUE(check(hb));
  hb.followed = true;
  EXPECT_NE(check(hb).error().find("dv_ml"), std::string::npos);
  hb.dv_ml = 420.0;
  hb.left_dv_ml = std::nan("");  // a lung without its own volume takes its share
  hb.right_dv_ml = 230.0;
  EXPECT_TRUE(check(hb));
  hb.right_dv_ml = 2e4;
  const Status s = check(hb);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("right_dv_ml: expected a volume change within +-8000 mL or NaN"), std::string::npos)
      << s.error();
  hb.right_dv_ml = INFINITY;
  EXPECT_FALSE(check(hb));
}

TEST(SyncWire, HeartbeatsAndStationsAreChecked) {
  lungar_sync_Heartbeat hb{1, 1, 1'700'000'000'000'000'000, 3.5, false, 0.0, 0.0, 0.0};
  EXPECT_TRUE(check(hb));
  hb.breath_t_s = kNaN;
  EXPECT_FALSE(check(hb));
  lungar_sync_Station st{};
  std::snprintf(st.name, sizeof st.name, "ward-3/instructor");
  st.role = 1;
  EXPECT_TRUE(check(st));
  st.role = 7;
  EXPECT_FALSE(check(st));
  st.role = 2;
  st.name[0] = '\0';
  EXPECT_FALSE(check(st));
}

TEST(SyncWire, ATraineesStatusIsCheckedNamingTheField) {
  lungar_sync_StationStatus s{};
  std::snprintf(s.name, sizeof s.name, "bed-2");
  s.state = 1;
  s.fps = 60.0;
  EXPECT_TRUE(check(s));
  s.state = 9;
  EXPECT_NE(check(s).error().find("lungar_station_status: state"), std::string::npos);
  s.state = 2;
  s.pose_age_ms = kNaN;
  EXPECT_NE(check(s).error().find("pose_age_ms"), std::string::npos);
  s.pose_age_ms = 1.0;
  s.breath_offset_ms = -1.0;
  EXPECT_NE(check(s).error().find("breath_offset_ms"), std::string::npos);
  s.breath_offset_ms = 0.0;
  s.name[0] = '\0';
  EXPECT_NE(check(s).error().find("name"), std::string::npos);
}
