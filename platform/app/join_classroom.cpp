/// @file join_classroom.cpp
/// @brief [sync] -> the station, wrapped around the Runtime's pose source and breathing clock.
#include "platform/app/join_classroom.h"

#include "drivers/breath/classroom/classroom_breathing.h"
#include "platform/runtime/patient_force.h"
#include "platform/runtime/scenario_patient.h"
#include "platform/sync/instructor_publisher.h"
#include "platform/sync/trainee_poses.h"

namespace lungar::platform::sync {

namespace {
/// A trainee's display shows what the instructor's console asks of the class (Trainee::ventilation_map_since).
class TraineeDisplay final : public DisplayRequests {
 public:
  explicit TraineeDisplay(std::shared_ptr<const classroom::ClassroomStation> station) : station_(std::move(station)) {}
  bool ventilation_map_since(std::uint64_t& version, bool& on) const override {
    return station_->trainee()->ventilation_map_since(version, on);
  }

 private:
  std::shared_ptr<const classroom::ClassroomStation> station_;
};
}  // namespace

Status can_draw(const std::shared_ptr<const sim::BakedAsset>& healthy,
                const std::shared_ptr<const sim::BakedAsset>& drawn, const sim::PathologyTimeline& timeline) {
  if (!healthy || !drawn) return fail("the loaded lungs are not kept: none of their pathologies can change");
  auto course = PathologyCourse::create(*healthy, *drawn, timeline);  // on the console's thread: the frame goes on
  if (!course) return fail(course.error());
  return ok();
}

Result<JoinedClassroom> join_classroom(const Settings& s, std::int64_t clock_skew_ns,
                                       const sim::BreathingScript& script, const LoadedLungs& lungs, std::int64_t t0_ns,
                                       const std::string& followed, RuntimeParts& parts,
                                       std::function<void(const std::string&)> log) {
  auto opened = classroom::ClassroomStation::open(s.sync, log, clock_skew_ns);
  if (!opened) return Error{opened.error()};
  JoinedClassroom joined;
  auto station = joined.station = std::make_shared<classroom::ClassroomStation>(opened.take());
  if (classroom::Instructor* instructor = station->instructor()) {
    if (Status shared = instructor->share_breathing(script.start, script.events, lungs.own, t0_ns); !shared)
      return shared.with_context("");
    parts.listeners.push_back(std::make_shared<InstructorPublisher>(station));
    if (!lungs.own.empty() && log) log("classroom: sharing the lungs' pathologies: " + sim::describe(lungs.own));
    if (!s.console.listen.empty()) {
      // The console changes the class as it runs: the instructor's own breath and lungs follow what it shares.
      // A simulated patient (the mock tracker) is the console's to turn; a tracked one is not.
      const bool simulated = s.trackers().source == drivers::TrackerSource::Mock;
      auto control =
          ClassControl::create({script.start, script.events, lungs.own, t0_ns, followed,
                                simulated ? std::optional<sim::OrientationTrack>(script.orientation) : std::nullopt},
                               station, log);
      if (!control) return control.with_context("");
      joined.control = control.take();
      if (simulated) parts.poses = std::make_unique<ScenarioPatient>(std::move(parts.poses), joined.control, t0_ns);
      parts.display = joined.control;
      joined.control->can_draw = [healthy = lungs.healthy, drawn = lungs.drawn](const sim::PathologyTimeline& t) {
        return can_draw(healthy, drawn, t);
      };
      parts.listeners.push_back(joined.control);
      parts.breathing = followed.empty() ? joined.control->breathing_clock()
                                         : joined.control->over_followed(std::move(parts.breathing));
      if (!lungs.healthy || !lungs.drawn) return fail("console: the instructor needs its loaded lungs to change them");
      parts.course = std::make_shared<ClassroomCourse>(parts.course, joined.control, lungs, log);
    }
  } else if (station->trainee() != nullptr) {
    parts.poses = std::make_unique<TraineePoses>(
        std::move(parts.poses), station,
        registration_isometry(s.registration.translation_mm, s.registration.rotation_wxyz));
    if (!lungs.healthy || !lungs.drawn) return fail("classroom: a trainee needs the loaded lungs to draw the instructor's");
    parts.course = std::make_shared<ClassroomCourse>(parts.course, station, lungs, log);
    parts.display = std::make_shared<TraineeDisplay>(station);
  }
  if (!s.console.listen.empty() && !joined.control)
    return fail("console: the console runs on the classroom's instructor; start this station with --sync instructor");
  parts.breathing = std::make_unique<classroom::ClassroomBreathing>(std::move(parts.breathing), station);
  return joined;
}

}  // namespace lungar::platform::sync
