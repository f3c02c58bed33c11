/// @file clearest_trace.h
/// @brief Several recordings of one session given (`--breath A --breath B ...`, e.g. the three markers of an
///        ExtMarker session): the one whose breathing is clearest, by sim/breathing/breath_clarity.h (the share of
///        its power at 6-42 breaths a minute over its first 60 s). Used by lungar and by lungar-breathe alike.
/// @ingroup breath
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"

namespace lungar::breath {

/// The clearest of `paths` (each a recorded trace), and in `said` one line naming it and every other one's share;
/// or the error that stops them being compared (a file that does not read, a source that is not a recording).
Result<std::string> clearest_trace(const std::vector<std::string>& paths, std::string& said);

}  // namespace lungar::breath
