// The classroom's frame side, with an instructor and a trainee in one process on a real Cyclone domain: the
// trainee's pose source hands the instructor's lung pose back through its own registration, its breathing clock
// follows the shared time base, and none of the per-frame calls (the instructor's listener, the trainee's pose
// source and breathing clock) allocates.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <string>
#include <thread>

#define LUNGAR_ALLOCATION_COUNTERS_ONLY
#include "../../sim/allocation_counter.h"
#include "config/base/clock.h"
#include "drivers/breath/classroom/classroom_breathing.h"
#include "drivers/breath/model/script_breathing.h"
#include "platform/app/scenario_adapter.h"
#include "platform/runtime/gl_math.h"
#include "platform/runtime/patient_force.h"
#include "platform/sync/instructor_publisher.h"
#include "platform/sync/trainee_poses.h"
#include "sync_test_support.h"

using namespace lungar;
using namespace lungar::platform;
using namespace lungar::platform::sync;
using namespace lungar::classroom;

namespace {

/// The trainee's own tracker: a fixed head, and a patient upright (what it would draw without the classroom).
class StillPoses final : public PoseSource {
 public:
  std::string describe() const override { return "still"; }
  drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const override {
    drivers::PoseSample s;
    s.role = role;
    s.flags = drivers::kPoseValid;
    s.t_arrival_ns = now_ns;
    return s;
  }
  drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t) const override {
    return latest(role, t_ns);
  }
  const char* state() const override { return "streaming"; }
  bool finished() const override { return false; }
  SourceCounters counters(double) const override { return {}; }
  void stop() override {}
};

classroom::SyncSettings sync_settings(classroom::SyncRole role) {
  classroom::SyncSettings s;
  s.role = role;
  s.classroom = lungar::testing::test_classroom("frame-side");
  s.domain = static_cast<int>(lungar::testing::test_domain());
  s.cyclonedds_xml = lungar::testing::kLoopbackXml;
  s.station = role == classroom::SyncRole::Instructor ? "instructor" : "trainee";
  return s;
}

}  // namespace

TEST(ClassroomFrameSide, TheTraineeDrawsTheInstructorsLungAndBreathWithoutAllocating) {
  auto quiet = [](const std::string&) {};
  auto instructor = ClassroomStation::open(sync_settings(classroom::SyncRole::Instructor), quiet);
  ASSERT_TRUE(instructor) << instructor.error();
  auto teacher = std::make_shared<ClassroomStation>(instructor.take());
  const std::int64_t t0 = monotonic_ns() - 2'000'000'000;  // the instructor has been breathing for 2 s
  auto script = platform::load_breathing_script(config::BreathingSettings{}, 60.0);
  ASSERT_TRUE(script);
  ASSERT_TRUE(teacher->instructor()->share_breathing(script->start, script->events, {}, t0));
  // The trainee's log is kept: its "sync lost" line says how long the instructor has been silent.
  std::mutex log_mutex;
  std::string trainee_log;
  auto keep = [&](const std::string& line) {
    std::lock_guard lock(log_mutex);
    trainee_log += line + "\n";
  };
  auto trainee = ClassroomStation::open(sync_settings(classroom::SyncRole::Trainee), keep);
  ASSERT_TRUE(trainee) << trainee.error();
  auto learner = std::make_shared<ClassroomStation>(trainee.take());

  // The trainee's registration turns the model 30 degrees about y; the instructor's lung is turned about x.
  const Eigen::Isometry3d registration =
      registration_isometry({10.0, -20.0, 5.0}, {0.9659258262890683, 0.0, 0.25881904510252074, 0.0});
  TraineePoses poses(std::make_unique<StillPoses>(), learner, registration);
  auto own = std::make_shared<const sim::BreathingScript>(script.take());
  ClassroomBreathing breathing(std::make_unique<breath::ScriptBreathing>(own, monotonic_ns()), learner);
  auto publisher = std::make_unique<InstructorPublisher>(teacher);
  FrameState frame;
  frame.lung_in_world = Eigen::Quaterniond(Eigen::AngleAxisd(-0.6, Eigen::Vector3d::UnitX()));
  frame.lung_origin_mm = Eigen::Vector3d(0.0, 700.0, 100.0);

  auto one_frame = [&](std::int64_t now) {
    frame.now_ns = now;
    frame.patient.t_arrival_ns = now;  // a new tracker reading every frame
    frame.breath.t_s = seconds_between(t0, now);
    if (publisher) publisher->on_frame(frame);
    sim::BreathingSample b = breathing.at(now);
    drivers::PoseSample p = poses.latest(drivers::Role::Patient, now);
    drivers::PoseSample h = poses.predicted(drivers::Role::Head, now, 0);
    return std::make_tuple(b, p, h);
  };
  const std::int64_t until = monotonic_ns() + 10'000'000'000;
  while (learner->state() != SyncState::InSync && monotonic_ns() < until) {
    one_frame(monotonic_ns());
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(learner->state(), SyncState::InSync);
  EXPECT_STREQ(poses.state(), "streaming");  // the own tracker's state again
  // In step comes with the instructor's first heartbeat or clock reply; the first shared pose (best effort, at the
  // tracker's rate) may come a little later, and until then the station's own patient tracker stands in.
  while (!learner->trainee()->patient_pose().valid() && monotonic_ns() < until) {
    one_frame(monotonic_ns());
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(learner->trainee()->patient_pose().valid()) << "no shared patient pose within 10 s";
  std::this_thread::sleep_for(std::chrono::milliseconds(100));

#if !defined(__SANITIZE_ADDRESS__)  // AddressSanitizer owns operator new: nothing is counted there
  const long before = lungar::testing::g_thread_allocations;
#endif
  drivers::PoseSample patient;
  sim::BreathingSample breath;
  std::int64_t now = 0;
  for (int i = 0; i < 200; ++i) {
    now = monotonic_ns();
    std::tie(breath, patient, std::ignore) = one_frame(now);
  }
#if !defined(__SANITIZE_ADDRESS__)
  EXPECT_EQ(lungar::testing::g_thread_allocations - before, 0);
#endif
  // The shared breathing time is the instructor's (2 s and more since its t0), not the trainee's own (0 s).
  EXPECT_NEAR(breath.t_s, seconds_between(t0, now), 0.005);
  // What the frame makes of the patient pose through this station's registration is the instructor's lung.
  ASSERT_TRUE(patient.valid());
  const Eigen::Isometry3d lung = lung_to_world(pose_isometry(patient), registration);
  EXPECT_TRUE(Eigen::Quaterniond(lung.rotation()).isApprox(frame.lung_in_world, 1e-9));
  EXPECT_TRUE(lung.translation().isApprox(frame.lung_origin_mm, 1e-9));

  // The instructor goes away: the status line says so, and the trainee breathes on on the shared time base.
  publisher.reset();
  teacher.reset();
  const std::int64_t gone = monotonic_ns();
  while (!learner->lost() && monotonic_ns() < gone + 5'000'000'000) {
    one_frame(monotonic_ns());
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_STREQ(poses.state(), "sync lost");
  {
    // The silence it reports is the one that made it lost: past the 250 ms limit, and not much more, since the
    // frames above check every 5 ms.
    std::lock_guard lock(log_mutex);
    const std::string said = "sync lost: no word from instructor 'instructor' for ";
    const auto at = trainee_log.find(said);
    ASSERT_NE(at, std::string::npos) << trainee_log;
    const long silent_ms = std::stol(trainee_log.substr(at + said.size()));
    EXPECT_GE(silent_ms, 250) << trainee_log;
    EXPECT_LE(silent_ms, 1500) << trainee_log;
  }
  now = monotonic_ns();
  EXPECT_NEAR(breathing.at(now).t_s, seconds_between(t0, now), 0.005);
}
