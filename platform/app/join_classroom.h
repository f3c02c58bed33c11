/// @file join_classroom.h
/// @brief Plugs the station [sync] asks for into a Runtime's parts: a trainee's patient pose source, shared
/// breathing clock and the instructor's lungs' course, the instructor's frame listener and the breathing and
/// pathologies it shares; the sync_* stats keys for every role (off included). The frame itself never knows.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "drivers/classroom/classroom_station.h"
#include "platform/app/settings.h"
#include "platform/runtime/runtime.h"
#include "platform/sync/class_control.h"
#include "platform/sync/classroom_course.h"
#include "sim/breathing/script.h"

namespace lungar::platform::sync {

/// Whether a station with these loaded lungs can draw `timeline` (every state of its course builds): the class
/// control's check before it shares a change.
Status can_draw(const std::shared_ptr<const sim::BakedAsset>& healthy,
                const std::shared_ptr<const sim::BakedAsset>& drawn, const sim::PathologyTimeline& timeline);

/// The station joined, and on an instructor with its console ([console] listen) the class control the console
/// drives (null without).
struct JoinedClassroom {
  std::shared_ptr<classroom::ClassroomStation> station;
  std::shared_ptr<ClassControl> control;
};

/// `script` is this station's own breathing, started at monotonic `t0_ns`, and `lungs.own` its pathologies on
/// the same time (the instructor shares both; a trainee, or an instructor with its console, needs `lungs`' assets
/// to draw lungs that change); `followed` names the breath's source when it is the patient's own (empty: the
/// model); `clock_skew_ns` lets a test pretend this station's clock is off. The station is returned for the run
/// loop (an instructor may have to stop when an older one turns up).
Result<JoinedClassroom> join_classroom(const Settings& s, std::int64_t clock_skew_ns,
                                       const sim::BreathingScript& script, const LoadedLungs& lungs, std::int64_t t0_ns,
                                       const std::string& followed, RuntimeParts& parts,
                                       std::function<void(const std::string&)> log);

}  // namespace lungar::platform::sync
