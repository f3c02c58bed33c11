/// @file run_limit.h
/// @brief How long a run lasts: --seconds when given, else a scenario's own length (so that a lesson is neither cut
///        short nor run past its end), else the demo's 10 s unless --frames alone limits it; and the log's words
///        for it.
/// @ingroup platform
#pragma once

#include <string>

#include "config/scenario.h"
#include "platform/app/runtime_options.h"

namespace lungar::platform {

/// The run's time limit in seconds (0: none, until stopped or --frames); `scenario`: the one that runs, or null.
double run_limit_s(const RuntimeOptions& o, const config::Scenario* scenario);

/// "running 75.0 s, the scenario's length (--seconds changes it) (Ctrl-C stops)" and the like.
std::string describe_limit(const RuntimeOptions& o, const config::Scenario* scenario);

}  // namespace lungar::platform
