/// @file run.h
/// @brief `lungar` as a user runs it: settings and command line -> asset, output, pose source, breathing ->
/// a Runtime -> frames until a limit, the window closes, a replay ends or a stop is asked -> the snapshot, the
/// stats JSON and a summary line.
/// @ingroup platform
#pragma once

#include <atomic>

#include "platform/app/settings.h"
#include "platform/app/runtime_options.h"

namespace lungar::platform {

/// Set from a signal handler (SIGINT, SIGTERM): the loop ends after the current frame and writes its outputs.
extern std::atomic<bool> g_stop_requested;

/// Returns the process exit code; errors are logged as one line naming the file or device and what was expected.
int run_runtime(const Settings& settings, const RuntimeOptions& options);

}  // namespace lungar::platform
