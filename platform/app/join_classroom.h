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
#include "platform/sync/classroom_course.h"
#include "sim/breathing/script.h"

namespace lungar::platform::sync {

/// `script` is this station's own breathing, started at monotonic `t0_ns`, and `lungs.own` its pathologies on
/// the same time (the instructor shares both; a trainee needs `lungs`' assets to draw the instructor's);
/// `clock_skew_ns` lets a test pretend this station's clock is off. The station is returned for the run loop
/// (an instructor may have to stop when an older one turns up).
Result<std::shared_ptr<classroom::ClassroomStation>> join_classroom(const Settings& s, std::int64_t clock_skew_ns,
                                                                    const sim::BreathingScript& script,
                                                                    const LoadedLungs& lungs, std::int64_t t0_ns,
                                                                    RuntimeParts& parts,
                                                                    std::function<void(const std::string&)> log);

}  // namespace lungar::platform::sync
