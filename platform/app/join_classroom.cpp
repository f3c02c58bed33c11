/// @file join_classroom.cpp
/// @brief [sync] -> the station, wrapped around the Runtime's pose source and breathing clock.
#include "platform/app/join_classroom.h"

#include "drivers/breath/classroom/classroom_breathing.h"
#include "platform/runtime/patient_force.h"
#include "platform/sync/instructor_publisher.h"
#include "platform/sync/trainee_poses.h"

namespace lungar::platform::sync {

Result<std::shared_ptr<classroom::ClassroomStation>> join_classroom(const Settings& s, std::int64_t clock_skew_ns,
                                                                    const sim::BreathingScript& script,
                                                                    const LoadedLungs& lungs, std::int64_t t0_ns,
                                                                    RuntimeParts& parts,
                                                                    std::function<void(const std::string&)> log) {
  auto opened = classroom::ClassroomStation::open(s.sync, log, clock_skew_ns);
  if (!opened) return Error{opened.error()};
  auto station = std::make_shared<classroom::ClassroomStation>(opened.take());
  if (classroom::Instructor* instructor = station->instructor()) {
    if (Status shared = instructor->share_breathing(script.start, script.events, lungs.own, t0_ns); !shared)
      return shared.with_context("");
    parts.listeners.push_back(std::make_shared<InstructorPublisher>(station));
    if (!lungs.own.empty() && log) log("classroom: sharing the lungs' pathologies: " + sim::describe(lungs.own));
  } else if (station->trainee() != nullptr) {
    parts.poses = std::make_unique<TraineePoses>(
        std::move(parts.poses), station,
        registration_isometry(s.registration.translation_mm, s.registration.rotation_wxyz));
    if (!lungs.healthy || !lungs.drawn) return fail("classroom: a trainee needs the loaded lungs to draw the instructor's");
    parts.course = std::make_shared<ClassroomCourse>(parts.course, station, lungs, log);
  }
  parts.breathing = std::make_unique<classroom::ClassroomBreathing>(std::move(parts.breathing), station);
  return station;
}

}  // namespace lungar::platform::sync
