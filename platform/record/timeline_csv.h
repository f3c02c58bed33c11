/// @file timeline_csv.h
/// @brief What a session record says at a time (the pathologies drawn, dV), and its debrief sheet: the events, the
///        console's actions, the timeline's changes and the pathologies drawn, one CSV row each.
/// @ingroup platform
#pragma once

#include <string>

#include "platform/record/session_record.h"

namespace lungar::platform::record {

/// The pathologies present at session time `s` as the frames say (the last frame at or before it; "" before any).
const std::string& pathologies_at(const SessionRecord& record, double s);
/// dV at session time `s`, linear between the frames around it (the first's before them, the last's after).
double dv_at(const SessionRecord& record, double s);

/// One CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string csv_field(const std::string& text);

/// A debrief sheet: one CSV row per event, console action, timeline change and change of the pathologies drawn, in
/// time order: session_s, breath_s, kind, user, text, pathologies (present then), dv_ml (then).
std::string timeline_csv(const SessionRecord& record);

}  // namespace lungar::platform::record
