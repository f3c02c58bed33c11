/// @file runtime.h
/// @brief The lungar runtime: tracker thread(s) -> poses; breathing dV(t); patient pose -> force SH; head pose ->
/// eye views; draw; swap or read back (DESIGN.md, "One frame").
#pragma once

#include <atomic>

#include "config/settings.h"
#include "platform/runtime/runtime_options.h"

namespace lungar::platform {

/// Set from a signal handler (SIGINT, SIGTERM): the loop ends after the current frame and writes its outputs.
extern std::atomic<bool> g_stop_requested;

/// Runs until the frame or time limit, the window is closed, the replay ends or a stop is requested. Returns the
/// process exit code; errors are logged as one line naming the file or device and what was expected.
int run_runtime(const config::Settings& settings, const RuntimeOptions& options);

}  // namespace lungar::platform
