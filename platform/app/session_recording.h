/// @file session_recording.h
/// @brief `lungar --session-record PATH`: where the session's record goes, and the recorder that run.cpp starts
///        before the first frame (platform/record/session_recorder.h) and the console notes the class's events into.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "platform/app/runtime_options.h"
#include "platform/app/settings.h"
#include "platform/record/session_recorder.h"
#include "platform/runtime/runtime.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::platform {

/// The record's file for --session-record `given`: `given` itself, or, when it is an existing folder,
/// FOLDER/<UTC date-time>-<station>.lungarsession.
std::string session_record_path(const std::string& given, const std::string& station);

/// One line when --session-record `given` cannot be written (a folder that is not there or not writable, a file
/// that exists: a record is never overwritten); checked before anything slow loads.
Status check_session_record_path(const std::string& given);

/// With --session-record, starts the session's record: its header from the settings and the loaded scene in
/// `parts`, the lungs' timeline from the start (`timeline`, noted at once) and its recorder among `parts`'
/// listeners, following `parts.course`'s pathologies; `t0`: the session's time zero (monotonic). Null without
/// --session-record. Call it after the sources are added and before the Runtime is made.
Result<std::shared_ptr<record::SessionRecorder>> start_session_recording(const Settings& s, const RuntimeOptions& o,
                                                                         const sim::PathologyTimeline& timeline,
                                                                         std::int64_t t0, RuntimeParts& parts);

/// Closes the record (null: nothing) and says where it is; false after a write error, said in the log.
bool finish_session_recording(const std::shared_ptr<record::SessionRecorder>& recorder);

}  // namespace lungar::platform
