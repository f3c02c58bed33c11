// The instructor's class control in one process with a trainee over loopback DDS: a console request becomes an
// event the instructor breathes and the trainee follows (a breath hold and its end, a pathology coming, one
// changing severity), a resumed breath never jumps, the requests that cannot be met are refused with one line
// and change nothing, and the live view says what is going on.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "config/scenario_load.h"
#include "platform/app/join_classroom.h"
#include "platform/app/scenario_adapter.h"
#include "platform/sync/class_control.h"
#include "room_support.h"
#include "sim/breathing/orientation.h"

using namespace lungar;
using classroom::ClassroomStation;

namespace {

const console::ConsoleUser kTeacher{"instructor", console::Role::Instructor};

/// An instructor whose class control runs with `lungs`, `followed` and a simulated patient's `posture` (none: the
/// patient is tracked), and a trainee of the same classroom.
struct ControlledRoom {
  std::shared_ptr<ClassroomStation> teacher, learner;
  std::shared_ptr<platform::sync::ClassControl> control;
  std::vector<std::string> lines;
  std::mutex lines_mutex;

  explicit ControlledRoom(const std::string& tag, sim::PathologyTimeline lungs = {}, std::string followed = "",
                          std::optional<sim::OrientationTrack> posture = std::nullopt) {
    const std::string room = lungar::testing::test_classroom(tag);
    auto quiet = [](const std::string&) {};
    auto instructor =
        ClassroomStation::open(lungar::testing::room_sync_settings(classroom::SyncRole::Instructor, room), quiet);
    EXPECT_TRUE(instructor) << instructor.error();
    teacher = std::make_shared<ClassroomStation>(instructor.take());
    auto script = platform::load_breathing_script(config::BreathingSettings{}, 60.0);
    EXPECT_TRUE(script);
    const std::int64_t t0 = monotonic_ns() - 1'000'000'000;  // the class has been going for 1 s
    EXPECT_TRUE(teacher->instructor()->share_breathing(script->start, script->events, lungs, t0));
    auto made = platform::sync::ClassControl::create({script->start, script->events, lungs, t0, followed, posture},
                                                     teacher, [this](const std::string& line) {
                                                       std::lock_guard lock(lines_mutex);
                                                       lines.push_back(line);
                                                     });
    EXPECT_TRUE(made) << made.error();
    control = made.take();
    control->can_draw = [](const sim::PathologyTimeline& t) {
      return platform::sync::can_draw(lungar::testing::procedural_lungs(), lungar::testing::procedural_lungs(), t);
    };
    auto trainee =
        ClassroomStation::open(lungar::testing::room_sync_settings(classroom::SyncRole::Trainee, room), quiet);
    EXPECT_TRUE(trainee) << trainee.error();
    learner = std::make_shared<ClassroomStation>(trainee.take());
  }

  /// Polls `done` every 2 ms for at most 10 s.
  template <class Done>
  static bool within_10_s(Done done) {
    const std::int64_t until = monotonic_ns() + 10'000'000'000;
    while (monotonic_ns() < until) {
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }

  /// The trainee's breathing at now.
  bool trainee_breath(sim::BreathingSample& out) const { return learner->trainee()->breathing(monotonic_ns(), out); }
};

}  // namespace

TEST(ClassControl, APausedBreathHoldsOnBothStationsAndResumesWithoutAJump) {
  ControlledRoom room("pause");
  sim::BreathingSample s;
  ASSERT_TRUE(ControlledRoom::within_10_s([&] { return room.trainee_breath(s); }));

  const console::ControlReply paused = room.control->control(kTeacher, {{"action", "breath_pause"}});
  ASSERT_EQ(paused.status, 200) << paused.body.dump();
  const double pause_at = paused.body["t_s"];
  EXPECT_EQ(room.control->control(kTeacher, {{"action", "breath_pause"}}).status, 409) << "paused already";
  // The trainee holds too, once the new revision has come and the hold's ramp is over.
  ASSERT_TRUE(ControlledRoom::within_10_s([&] { return room.trainee_breath(s) && s.phase == sim::BreathPhase::Hold; }));
  EXPECT_LT(s.t_s, pause_at + 2.0) << "the hold came with the request, not on some later event";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the breath slows to a stop over 0.2 s
  ASSERT_TRUE(room.trainee_breath(s));
  const double held_ml = s.dv_ml;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_TRUE(room.trainee_breath(s));
  EXPECT_NEAR(s.dv_ml, held_ml, 1e-9) << "a hold stands still";
  EXPECT_EQ(nlohmann::json::parse(room.control->snapshot_json())["breath"]["state"], "paused");

  const console::ControlReply resumed = room.control->control(kTeacher, {{"action", "breath_resume"}});
  ASSERT_EQ(resumed.status, 200) << resumed.body.dump();
  const double resume_at = resumed.body["t_s"];
  // The instructor's own breath across the resume, in 10 ms steps: no step larger than 5 mL.
  const sim::BreathingDriver& d = room.control->driver();
  double largest_ml = 0;
  for (double t = resume_at - 1.0; t < resume_at + 4.0; t += 0.01)
    largest_ml = std::max(largest_ml, std::abs(d.at(t + 0.01).dv_ml - d.at(t).dv_ml));
  EXPECT_LE(largest_ml, 5.0);
  EXPECT_GT(std::abs(d.at(resume_at + 3.0).dv_ml - d.at(resume_at).dv_ml), 20.0) << "it breathes again";
  ASSERT_TRUE(ControlledRoom::within_10_s(
      [&] { return room.trainee_breath(s) && s.phase != sim::BreathPhase::Hold && s.t_s > resume_at + 0.5; }));
}

TEST(ClassControl, APathologyAddedReachesTheTraineeAndChangesSeverityInOneEvent) {
  ControlledRoom room("pathology");
  std::uint64_t version = 0;
  sim::PathologyTimeline seen;
  const console::ControlReply added =
      room.control->control(kTeacher, {{"action", "pathology_add"}, {"spec", "pneumothorax:right:30"}, {"over_s", 2}});
  ASSERT_EQ(added.status, 200) << added.body.dump();
  ASSERT_TRUE(ControlledRoom::within_10_s(
      [&] { return room.learner->trainee()->lungs_since(version, seen) && !seen.events.empty(); }));
  ASSERT_EQ(seen.events.size(), 1u);
  EXPECT_EQ(seen.events[0].add, "pneumothorax:right:30");
  EXPECT_DOUBLE_EQ(seen.events[0].over_s, 2.0);
  EXPECT_DOUBLE_EQ(seen.events[0].at_s, added.body["t_s"].get<double>());
  // The instructor's own lungs follow the same timeline (its course's feed).
  std::uint64_t own_version = 0;
  sim::PathologyTimeline own;
  ASSERT_TRUE(room.control->lungs_since(own_version, own));
  EXPECT_EQ(own, seen);

  const console::ControlReply worse = room.control->control(
      kTeacher, {{"action", "pathology_severity"}, {"spec", "pneumothorax:right:30"}, {"to", "pneumothorax:right:50"}});
  ASSERT_EQ(worse.status, 200) << worse.body.dump();
  ASSERT_TRUE(ControlledRoom::within_10_s(
      [&] { return room.learner->trainee()->lungs_since(version, seen) && seen.events.size() == 2; }));
  EXPECT_EQ(seen.events[1].remove, "pneumothorax:right:30");
  EXPECT_EQ(seen.events[1].add, "pneumothorax:right:50");
  EXPECT_EQ(sim::present_after(seen, 2), std::vector<std::string>{"pneumothorax:right:50"});
  const auto view = nlohmann::json::parse(room.control->snapshot_json());
  EXPECT_EQ(view["events"].back()["kind"], "pathology severity");
  EXPECT_EQ(view["events"].back()["user"], "instructor");
}

TEST(ClassControl, RequestsThatCannotBeMetAreRefusedWithOneLineAndChangeNothing) {
  ControlledRoom room("refused");
  const std::uint32_t revision = room.teacher->instructor()->revision();
  const std::pair<nlohmann::json, std::string> cases[] = {
      {{{"action", "pathology_add"}, {"spec", "pneumothorax:middle:30"}}, "pneumothorax"},
      {{{"action", "pathology_add"}, {"spec", "consolidation:right:lower"}}, "must be the drawn lungs' own"},
      {{{"action", "pathology_remove"}, {"spec", "pneumothorax:right:30"}}, "is not present then"},
      {{{"action", "pathology_add"}, {"spec", "pneumothorax:right:30"}, {"over_s", -1}}, "over_s"},
      {{{"action", "breath_set"}, {"rate_bpm", "fast"}}, "rate_bpm: expected a number"},
      {{{"action", "breath_set"}, {"preset", "asthma"}}, "preset: expected normal, emphysema or fibrosis"},
      {{{"action", "breath_set"}, {"tidal_volume_ml", 9000}}, "tidal"},
      {{{"action", "breath_resume"}}, "not paused"},
      {{{"action", "dance"}}, "action: expected one of"},
      {{{"action", "marker"}}, "text: expected a text"},
  };
  for (const auto& [request, says] : cases) {
    SCOPED_TRACE(request.dump());
    const console::ControlReply r = room.control->control(kTeacher, request);
    EXPECT_GE(r.status, 400);
    EXPECT_NE(r.body["error"].get<std::string>().find(says), std::string::npos) << r.body.dump();
  }
  EXPECT_EQ(room.teacher->instructor()->revision(), revision) << "nothing was shared";
  std::uint64_t version = 0;
  sim::PathologyTimeline lungs;
  EXPECT_FALSE(room.control->lungs_since(version, lungs)) << "the lungs never changed";
}

/// A followed breath for the test: a steady 300 mL, as a trace held at one level would give, on the breathing time
/// of a class started at t0_ns.
class SteadyFollowed final : public breath::BreathingClock {
 public:
  explicit SteadyFollowed(std::int64_t t0_ns) : t0_ns_(t0_ns) {}
  sim::BreathingSample at(std::int64_t now_ns) const override {
    sim::BreathingSample s;
    s.t_s = seconds_between(t0_ns_, now_ns);
    s.dv_ml = s.v_ml = 300.0;
    return s;
  }

 private:
  std::int64_t t0_ns_;
};

TEST(ClassControl, AFollowedBreathIsTakenOverByTheConsoleAndGivenBackWithoutAJump) {
  ControlledRoom room("followed", {}, "trace");
  platform::sync::ClassControl& c = *room.control;
  EXPECT_EQ(c.control(kTeacher, {{"action", "breath_follow"}}).status, 409) << "it follows the trace already";
  const std::unique_ptr<breath::BreathingClock> breathing =
      c.over_followed(std::make_unique<SteadyFollowed>(c.t0_ns()));
  // The instructor's breath in 10 ms steps for `seconds` on from the last: the largest step, and the last dV.
  std::int64_t now = monotonic_ns();
  const auto run = [&](double seconds, double& last_ml) {
    double largest = 0, before = last_ml;
    for (int i = 0; i < seconds * 100; ++i) {
      now += 10'000'000;
      last_ml = breathing->at(now).dv_ml;
      largest = std::max(largest, std::abs(last_ml - before));
      before = last_ml;
    }
    return largest;
  };
  double last = breathing->at(now).dv_ml;
  run(0.5, last);
  EXPECT_DOUBLE_EQ(last, 300.0) << "the followed breath";

  const console::ControlReply paused = c.control(kTeacher, {{"action", "breath_pause"}});
  ASSERT_EQ(paused.status, 200) << paused.body.dump();
  EXPECT_TRUE(c.breath_taken_over());
  auto view = nlohmann::json::parse(c.snapshot_json())["breath"];
  EXPECT_EQ(view["source"], "model, in place of trace");
  EXPECT_EQ(view["taken_over"], true);
  EXPECT_LE(run(3.0, last), 5.0 + 1e-9) << "over to the model's held breath at the handover rate (500 mL/s)";
  const double held = c.driver().at(seconds_between(c.t0_ns(), now)).dv_ml;
  EXPECT_NEAR(last, held, 1e-6) << "then the model's own";

  ASSERT_EQ(c.control(kTeacher, {{"action", "breath_follow"}}).status, 200);
  EXPECT_FALSE(c.breath_taken_over());
  EXPECT_LE(run(3.0, last), 5.0 + 1e-9) << "back to the trace at the handover rate";
  EXPECT_DOUBLE_EQ(last, 300.0);
  EXPECT_EQ(nlohmann::json::parse(c.snapshot_json())["events"].back()["kind"], "breath follow");
  // A tracked patient's posture is not the console's: there is a real patient (or mannequin) there to turn.
  const console::ControlReply turned = c.control(kTeacher, {{"action", "posture_set"}, {"posture", "supine"}});
  EXPECT_EQ(turned.status, 409);
  EXPECT_NE(turned.body["error"].get<std::string>().find("a tracker measures"), std::string::npos)
      << turned.body.dump();
  EXPECT_FALSE(nlohmann::json::parse(c.snapshot_json())["posture"]["simulated"].get<bool>());
}

// The trainee's side of a take-over: the instructor's frames (run here, 100 a second) send the dV they draw in their
// heartbeats, the followed breath's and then the console's held one, which the trainee draws too.
TEST(ClassControl, ATraineeGoesOverToTheConsolesBreathWhenItTakesTheFollowedOneOver) {
  ControlledRoom room("takeover", {}, "trace");
  platform::sync::ClassControl& c = *room.control;
  classroom::Instructor& instructor = *room.teacher->instructor();
  instructor.share_followed_breath();
  const std::unique_ptr<breath::BreathingClock> breathing =
      c.over_followed(std::make_unique<SteadyFollowed>(c.t0_ns()));
  sim::BreathingSample seen;
  // Frames for `seconds`: the instructor draws and shares; `ok` of the trainee's breath in 30 frames running (0.3 s)
  // ends them early.
  const auto frames = [&](double seconds, auto ok) {
    for (int i = 0, running = 0; i < seconds * 100; ++i) {
      const std::int64_t now = monotonic_ns();
      instructor.frame_breath(now, breathing->at(now));
      running = room.trainee_breath(seen) && ok(seen) ? running + 1 : 0;
      if (running == 30) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  };
  ASSERT_TRUE(frames(10.0, [](const sim::BreathingSample& s) { return std::abs(s.dv_ml - 300.0) < 1.0; }))
      << "the trainee draws the followed 300 mL; it draws " << seen.dv_ml;
  ASSERT_EQ(c.control(kTeacher, {{"action", "breath_pause"}}).status, 200);
  ASSERT_TRUE(frames(10.0, [](const sim::BreathingSample& s) { return s.phase == sim::BreathPhase::Hold; }));
  const std::int64_t held_at = monotonic_ns();
  ASSERT_TRUE(frames(5.0,
                     [&](const sim::BreathingSample& s) {
                       return std::abs(s.dv_ml - c.driver().at(seconds_between(c.t0_ns(), monotonic_ns())).dv_ml) < 1.0;
                     }))
      << "the trainee's breath is the console's held one; it draws " << seen.dv_ml;
  EXPECT_LT(seconds_between(held_at, monotonic_ns()), 3.0);
}

TEST(ClassControl, TheVentilationMapAskedReachesTheTraineeAndTheInstructorsOwnDisplay) {
  ControlledRoom room("display");
  std::uint64_t trainee_version = 0, own_version = 0;
  bool on = false;
  EXPECT_FALSE(room.control->ventilation_map_since(own_version, on)) << "nothing asked yet: each display its own";
  EXPECT_TRUE(nlohmann::json::parse(room.control->snapshot_json())["display"]["ventilation_map"].is_null());
  // The trainee has the class before the request: it shows its own choice until the console asks.
  ASSERT_TRUE(ControlledRoom::within_10_s([&] {
    sim::BreathingSample s;
    return room.trainee_breath(s);
  }));
  EXPECT_FALSE(room.learner->trainee()->ventilation_map_since(trainee_version, on));

  const console::ControlReply shown =
      room.control->control(kTeacher, {{"action", "display_set"}, {"ventilation_map", true}});
  ASSERT_EQ(shown.status, 200) << shown.body.dump();
  ASSERT_TRUE(
      ControlledRoom::within_10_s([&] { return room.learner->trainee()->ventilation_map_since(trainee_version, on); }));
  EXPECT_TRUE(on);
  ASSERT_TRUE(room.control->ventilation_map_since(own_version, on));
  EXPECT_TRUE(on);
  EXPECT_FALSE(room.control->ventilation_map_since(own_version, on)) << "told once";
  EXPECT_EQ(nlohmann::json::parse(room.control->snapshot_json())["display"]["ventilation_map"], true);

  // A pathology shared after it keeps the map on (the same request travels with every revision): the trainee is
  // not told again, so a trainee's own V key stands.
  ASSERT_EQ(room.control->control(kTeacher, {{"action", "pathology_add"}, {"spec", "pneumothorax:right:30"}}).status,
            200);
  std::uint64_t lungs_version = 0;
  sim::PathologyTimeline seen;
  ASSERT_TRUE(ControlledRoom::within_10_s(
      [&] { return room.learner->trainee()->lungs_since(lungs_version, seen) && !seen.events.empty(); }));
  EXPECT_FALSE(room.learner->trainee()->ventilation_map_since(trainee_version, on));

  ASSERT_EQ(room.control->control(kTeacher, {{"action", "display_set"}, {"ventilation_map", false}}).status, 200);
  ASSERT_TRUE(
      ControlledRoom::within_10_s([&] { return room.learner->trainee()->ventilation_map_since(trainee_version, on); }));
  EXPECT_FALSE(on);
  const console::ControlReply bad =
      room.control->control(kTeacher, {{"action", "display_set"}, {"ventilation_map", "yes"}});
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(bad.body["error"].get<std::string>().find("ventilation_map: expected true or false"), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(room.control->snapshot_json())["events"].back()["text"], "ventilation map off");
}

/// The angle between two orientations, degrees.
double degrees_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b) * 180.0 / M_PI;
}

/// A drill as a station keeps it in its scenarios folder: supine, a pneumothorax at 4 s, fast breathing at 6 s, the
/// pneumothorax decompressed at 20 s.
platform::sync::ClassScenario drill() {
  auto sc = config::load_scenario_from_string(R"(
name = "drill"
description = "supine; a right pneumothorax at 4 s, decompressed at 20 s"
duration_s = 30.0
[start]
preset = "normal"
rate_bpm = 14.0
tidal_volume_ml = 500.0
pose = "supine"
[[event]]
at_s = 4.0
kind = "pathology"
add = "pneumothorax:right:30"
over_s = 2.0
[[event]]
at_s = 6.0
kind = "change"
rate_bpm = 24.0
[[event]]
at_s = 20.0
kind = "pathology"
remove = "pneumothorax:right:30"
over_s = 3.0
)",
                                              "drill.toml");
  EXPECT_TRUE(sc) << sc.error();
  auto script = platform::make_breathing_script(*sc);
  EXPECT_TRUE(script) << script.error();
  auto made = platform::sync::ClassScenario::create(*sc, *script);
  EXPECT_TRUE(made) << made.error();
  return made.take();
}

/// The class's pathology events as the instructor shares them now.
sim::PathologyTimeline class_lungs(const platform::sync::ClassControl& c) {
  std::uint64_t version = 0;
  sim::PathologyTimeline lungs;
  c.lungs_since(version, lungs);
  return lungs;
}

TEST(ClassControl, AScenarioStartsPausesJumpsAndStopsOnTheRunningClass) {
  auto upright = sim::OrientationTrack::create(sim::pose_rotation(Pose::Upright), {});
  ASSERT_TRUE(upright);
  ControlledRoom room("scenario", {}, "", upright.take());
  platform::sync::ClassControl& c = *room.control;
  c.scenarios = {drill()};
  const auto ask = [&](nlohmann::json request) { return c.control(kTeacher, request); };

  const console::ControlReply unknown = ask({{"action", "scenario_load"}, {"name", "tour"}});
  EXPECT_EQ(unknown.status, 400);
  EXPECT_NE(unknown.body["error"].get<std::string>().find("scenarios (drill)"), std::string::npos) << unknown.body;
  EXPECT_EQ(ask({{"action", "scenario_start"}}).status, 409) << "nothing loaded";
  ASSERT_EQ(ask({{"action", "scenario_load"}, {"name", "drill"}}).status, 200);
  nlohmann::json view = nlohmann::json::parse(c.snapshot_json())["scenario"];
  EXPECT_EQ(view["loaded"]["phase"], "ready");
  ASSERT_EQ(view["loaded"]["cues"].size(), 3u);
  EXPECT_EQ(view["loaded"]["cues"][0]["text"], "add pneumothorax:right:30 over 2.0 s");

  // Started: the class goes to the scenario's start (supine, 14/min) over 2 s, then its events follow on time.
  const console::ControlReply started = ask({{"action", "scenario_start"}});
  ASSERT_EQ(started.status, 200) << started.body.dump();
  const double t0 = started.body["t_s"].get<double>() + platform::sync::ClassControl::kSettleS;
  EXPECT_LT(degrees_between(c.orientation_at(t0), sim::pose_rotation(Pose::Supine)), 1e-6);
  sim::PathologyTimeline lungs = class_lungs(c);
  ASSERT_EQ(lungs.events.size(), 2u) << sim::describe(lungs);
  EXPECT_NEAR(lungs.events[0].at_s, t0 + 4.0, 1e-9);
  EXPECT_EQ(lungs.events[0].add, "pneumothorax:right:30");
  EXPECT_NEAR(lungs.events[1].at_s, t0 + 20.0, 1e-9);
  EXPECT_NEAR(c.driver().pattern_at(t0 + 1.0).params.rate_bpm, 14.0, 1e-9);
  EXPECT_NEAR(c.driver().pattern_at(t0 + 25.0).params.rate_bpm, 24.0, 1e-9);
  std::uint64_t version = 0;
  sim::PathologyTimeline seen;
  ASSERT_TRUE(ControlledRoom::within_10_s(
      [&] { return room.learner->trainee()->lungs_since(version, seen) && seen.events.size() == 2; }));
  EXPECT_EQ(seen, lungs) << "the trainee has the scenario's steps";

  // Paused before its first event: what had not begun goes, the breath stays as it was started.
  ASSERT_EQ(ask({{"action", "scenario_pause"}}).status, 200);
  EXPECT_TRUE(class_lungs(c).events.empty());
  EXPECT_NEAR(c.driver().pattern_at(t0 + 25.0).params.rate_bpm, 14.0, 1e-9);
  view = nlohmann::json::parse(c.snapshot_json())["scenario"]["loaded"];
  EXPECT_EQ(view["phase"], "paused");
  EXPECT_LT(view["t_s"].get<double>(), 0.5) << "it stood at its start";

  // Jumped to the decompression while paused: the class gets what the scenario has by then (the pneumothorax,
  // 24/min) and waits there.
  const console::ControlReply jumped = ask({{"action", "scenario_jump"}, {"cue", 2}});
  ASSERT_EQ(jumped.status, 200) << jumped.body.dump();
  const double t1 = jumped.body["t_s"].get<double>();
  lungs = class_lungs(c);
  ASSERT_EQ(lungs.events.size(), 1u) << sim::describe(lungs);
  EXPECT_EQ(lungs.events[0].add, "pneumothorax:right:30");
  EXPECT_NEAR(lungs.events[0].at_s, t1, 1e-9);
  EXPECT_NEAR(c.driver().pattern_at(t1 + 20.0).params.rate_bpm, 24.0, 1e-9);
  EXPECT_EQ(nlohmann::json::parse(c.snapshot_json())["scenario"]["loaded"]["phase"], "paused");

  // Resumed from there: the decompression follows once the class has settled, which waits for the start's turn
  // to supine (still under way: everything here happens within a fraction of a second).
  const console::ControlReply resumed = ask({{"action", "scenario_start"}});
  ASSERT_EQ(resumed.status, 200) << resumed.body.dump();
  EXPECT_NEAR(resumed.body["scenario_s"].get<double>(), 20.0, 1e-9);
  lungs = class_lungs(c);
  ASSERT_EQ(lungs.events.size(), 2u) << sim::describe(lungs);
  EXPECT_EQ(lungs.events[1].remove, "pneumothorax:right:30");
  EXPECT_NEAR(lungs.events[1].at_s, t0 + platform::sync::ClassControl::kSettleS, 1e-9);
  EXPECT_EQ(ask({{"action", "scenario_load"}, {"name", "drill"}}).status, 409) << "stop it first";

  // Stopped: the decompression not yet begun goes; the class keeps what it has.
  ASSERT_EQ(ask({{"action", "scenario_stop"}}).status, 200);
  lungs = class_lungs(c);
  ASSERT_EQ(lungs.events.size(), 1u) << sim::describe(lungs);
  EXPECT_EQ(lungs.events[0].add, "pneumothorax:right:30");
  EXPECT_EQ(nlohmann::json::parse(c.snapshot_json())["scenario"]["loaded"]["phase"], "stopped");
  EXPECT_EQ(ask({{"action", "scenario_jump"}, {"cue", 3}}).status, 400) << "three cues: 0 to 2";
  const auto events = nlohmann::json::parse(c.snapshot_json())["events"];
  EXPECT_EQ(events.back()["kind"], "scenario stop");
  EXPECT_EQ(events.back()["user"], "instructor");
}

TEST(ClassControl, ASimulatedPatientTurnsToThePostureAskedAfterAnyTurnUnderWay) {
  // The scenario turns the patient to prone at 40 s (the class has been going for 1 s).
  const sim::Turn scripted{40.0, 4.0, sim::pose_rotation(Pose::Prone)};
  auto track = sim::OrientationTrack::create(sim::pose_rotation(Pose::Upright), {scripted});
  ASSERT_TRUE(track) << track.error();
  ControlledRoom room("posture", {}, "", track.take());
  const platform::sync::ClassControl& c = *room.control;
  EXPECT_TRUE(nlohmann::json::parse(room.control->snapshot_json())["posture"]["simulated"].get<bool>());

  const console::ControlReply supine =
      room.control->control(kTeacher, {{"action", "posture_set"}, {"posture", "supine"}, {"over_s", 2}});
  ASSERT_EQ(supine.status, 200) << supine.body.dump();
  const double at = supine.body["t_s"];
  EXPECT_LT(degrees_between(c.orientation_at(at - 0.01), sim::pose_rotation(Pose::Upright)), 1e-6) << "not before";
  EXPECT_NEAR(degrees_between(c.orientation_at(at + 1.0), sim::pose_rotation(Pose::Upright)), 45.0, 1.0)
      << "half way at half the time (smoothstep)";
  EXPECT_LT(degrees_between(c.orientation_at(at + 2.0), sim::pose_rotation(Pose::Supine)), 1e-6);
  // Asked again at once: the second turn waits for the first to end.
  const console::ControlReply left =
      room.control->control(kTeacher, {{"action", "posture_set"}, {"posture", "left_lateral"}, {"over_s", 3}});
  ASSERT_EQ(left.status, 200) << left.body.dump();
  EXPECT_NEAR(left.body["t_s"].get<double>(), at + 2.0, 1e-9);
  EXPECT_LT(degrees_between(c.orientation_at(at + 5.0), sim::pose_rotation(Pose::LeftLateral)), 1e-6);
  // The scenario's own turn is still coming, from wherever the console left the patient.
  EXPECT_LT(degrees_between(c.orientation_at(45.0), sim::pose_rotation(Pose::Prone)), 1e-6);
  const console::ControlReply crossing =
      room.control->control(kTeacher, {{"action", "posture_set"}, {"posture", "supine"}, {"over_s", 100}});
  EXPECT_EQ(crossing.status, 409);
  EXPECT_NE(crossing.body["error"].get<std::string>().find("turns the patient at 40.0 s"), std::string::npos)
      << crossing.body.dump();
  const console::ControlReply unknown =
      room.control->control(kTeacher, {{"action", "posture_set"}, {"posture", "sideways"}});
  EXPECT_EQ(unknown.status, 400);
  EXPECT_NE(unknown.body["error"].get<std::string>().find("posture: expected upright"), std::string::npos)
      << unknown.body.dump();
  EXPECT_LT(degrees_between(c.orientation_at(at + 5.0), sim::pose_rotation(Pose::LeftLateral)), 1e-6)
      << "a refused request changed nothing";
  const auto view = nlohmann::json::parse(room.control->snapshot_json());
  EXPECT_EQ(view["events"].back()["kind"], "posture");
  EXPECT_EQ(view["events"].back()["text"], "left_lateral over 3.0 s");
}

TEST(ClassControl, TheLiveViewShowsTheFramesAndTheTraineesStatus) {
  ControlledRoom room("view");
  platform::FrameState f;
  f.breath.t_s = 1.0;
  f.breath.dv_ml = 123.0;
  f.lung_in_world = Eigen::Quaterniond(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  f.gravity_lung = sim::pose_rotation(Pose::Supine).inverse() * Eigen::Vector3d(0, 0, -1);
  room.control->on_frame(f);
  // The trainee sends its status about twice a second; the instructor lists it by name.
  nlohmann::json view;
  ASSERT_TRUE(ControlledRoom::within_10_s([&] {
    view = nlohmann::json::parse(room.control->snapshot_json());
    return !view["stations"].empty();
  }));
  EXPECT_EQ(view["stations"][0]["name"], "trainee");
  EXPECT_EQ(view["samples"].back()[1], 123.0);
  EXPECT_NEAR(std::abs(view["orientation"]["pitch_deg"].get<double>()), 90.0, 1e-6);
  EXPECT_EQ(view["orientation"]["posture"], "supine");
  EXPECT_EQ(view["station"], "instructor");
  EXPECT_FALSE(view["presets"].empty());
  EXPECT_NE(view["pathology_forms"].dump().find("pneumothorax"), std::string::npos);
  EXPECT_EQ(room.control->timeline_csv().rfind("t_s,kind,user,text\n", 0), 0u);
}
