// A trainee's lungs in one process, on real Cyclone DDS over loopback: its own until the instructor's pathologies
// arrive, then the instructor's course on the instructor's breathing time (a pneumothorax dropped 1 s into the
// instructor's breathing is there on a trainee that joins 2 s in); a consolidation its lungs were not loaded
// with is said and its own lungs kept.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "platform/app/scenario_adapter.h"
#include "platform/sync/classroom_course.h"
#include "room_support.h"
#include "sim/bake/bake.h"
#include "sim/force/dependent_collapse.h"
#include "sim/pathology/pathology.h"

using namespace lungar;
using classroom::ClassroomStation;

namespace {

std::shared_ptr<const sim::BakedAsset> healthy() { return lungar::testing::procedural_lungs(); }

std::size_t right_of(const sim::BakedAsset& a) { return a.lungs[0].name == "right" ? 0 : 1; }

/// An instructor breathing for 2 s with `lungs`, and a trainee drawing healthy lungs through a ClassroomCourse.
struct Room {
  std::vector<std::string> lines;  // first: the course's builder may still log while the course goes
  std::mutex lines_mutex;
  std::shared_ptr<ClassroomStation> teacher, learner;
  std::unique_ptr<platform::ClassroomCourse> course;

  explicit Room(const sim::PathologyTimeline& lungs, const std::string& name) {
    const std::string room = lungar::testing::test_classroom(name);
    auto quiet = [](const std::string&) {};
    auto instructor =
        ClassroomStation::open(lungar::testing::room_sync_settings(classroom::SyncRole::Instructor, room), quiet);
    EXPECT_TRUE(instructor) << instructor.error();
    teacher = std::make_shared<ClassroomStation>(instructor.take());
    auto script = platform::load_breathing_script(config::BreathingSettings{}, 60.0);
    EXPECT_TRUE(script);
    const std::int64_t t0 = monotonic_ns() - 2'000'000'000;  // the instructor has been breathing for 2 s
    EXPECT_TRUE(teacher->instructor()->share_breathing(script->start, script->events, lungs, t0));
    auto trainee =
        ClassroomStation::open(lungar::testing::room_sync_settings(classroom::SyncRole::Trainee, room), quiet);
    EXPECT_TRUE(trainee) << trainee.error();
    learner = std::make_shared<ClassroomStation>(trainee.take());
    course = std::make_unique<platform::ClassroomCourse>(
        nullptr, learner, platform::LoadedLungs{healthy(), healthy(), sim::PatientState::of(*healthy()), {}},
        [this](const std::string& line) {
          std::lock_guard lock(lines_mutex);
          lines.push_back(line);
        });
  }

  /// Frames every 5 ms until `done` says so of the course's shapes, or 20 s.
  template <class Done>
  bool frames_until(Done done) {
    const std::int64_t until = monotonic_ns() + 20'000'000'000;
    while (monotonic_ns() < until) {
      if (done(course->at(monotonic_ns()))) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }

  std::string log() {
    std::lock_guard lock(lines_mutex);
    std::string all;
    for (const std::string& l : lines) all += l + "\n";
    return all;
  }
};

nlohmann::json stats_of(const platform::LungCourse& course) {
  nlohmann::json j;
  course.add_stats(j);
  return j;
}

}  // namespace

TEST(ClassroomCourse, ATraineeDrawsTheInstructorsPathologiesOnTheInstructorsTime) {
  const sim::PathologyTimeline lungs{{"ards:0.6"}, {{1.0, 0.5, "pneumothorax:right:30:tension", ""}}};
  Room room(lungs, "course");
  const std::size_t right = right_of(*healthy());
  EXPECT_DOUBLE_EQ(room.course->at(monotonic_ns())[right].figures.rest_volume_ml,
                   healthy()->lungs[right].rest_volume_ml)
      << "its own lungs before it hears the instructor";
  EXPECT_EQ(stats_of(*room.course)["sync_lungs"], "own");

  sim::BakedAsset sick = *healthy();
  sim::PatientState sick_patient = sim::PatientState::of(sick);
  ASSERT_TRUE(sim::apply_pathologies(sick, sick_patient, {"ards:0.6", "pneumothorax:right:30:tension"}));
  const double collapsed_ml = sick.lungs[right].rest_volume_ml;
  ASSERT_LT(collapsed_ml, 0.8 * healthy()->lungs[right].rest_volume_ml);
  // The pneumothorax came 1 s into the instructor's breathing and was whole at 1.5 s: the trainee, joining 2 s
  // in, draws it collapsed at once, not coming over its own first 1.5 s.
  ASSERT_TRUE(room.frames_until([&](const std::vector<sim::LungShape>& shapes) {
    return std::abs(shapes[right].figures.rest_volume_ml - collapsed_ml) < 1e-6;
  })) << room.log();
  const std::vector<sim::LungShape> now = room.course->at(monotonic_ns());
  ASSERT_TRUE(now[right].figures.collapse) << "the ARDS's collapse of the force";
  EXPECT_DOUBLE_EQ(now[right].figures.collapse->severity(), 0.6);
  EXPECT_NEAR(now[right].figures.centre[0], sick.lungs[right].centre[0], 1e-3) << "the mediastinum pushed over";
  const auto j = stats_of(*room.course);
  EXPECT_EQ(j["sync_lungs"], "instructor");
  EXPECT_EQ(j["pathologies"], (std::vector<std::string>{"ards:0.6", "pneumothorax:right:30:tension"}));
  EXPECT_NE(room.log().find("classroom: drawing the instructor's lungs: ards:0.6, then pneumothorax:right:30:tension "
                            "comes at 1.0 s over 0.5 s"),
            std::string::npos)
      << room.log();
}

TEST(ClassroomCourse, ALungTheTraineeCannotDrawIsSaidAndItsOwnKept) {
  Room room({{"consolidation:right:lower"}, {}}, "consolidation");
  const std::size_t right = right_of(*healthy());
  ASSERT_TRUE(room.frames_until([&](const std::vector<sim::LungShape>&) {
    return room.log().find("cannot draw the instructor's lungs") != std::string::npos;
  })) << room.log();
  EXPECT_NE(room.log().find("(a consolidation) must be the drawn lungs' own"), std::string::npos) << room.log();
  EXPECT_DOUBLE_EQ(room.course->at(monotonic_ns())[right].figures.rest_volume_ml,
                   healthy()->lungs[right].rest_volume_ml);
  EXPECT_EQ(stats_of(*room.course)["sync_lungs"], "own");
}
