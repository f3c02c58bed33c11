/// @file xr_runtime_quirks.h
/// @brief Known runtime failures lungar refuses to walk into. Monado 25 with no display to open and no null
/// compositor fails to start its compositor in xrBeginSession, and its frame thread then crashes the process:
/// lungar says so in one line before making the session.
#pragma once

#include <functional>
#include <string>

#include "config/base/result.h"

namespace lungar::platform::openxr {

/// Reads an environment variable (null when unset); std::getenv by default, a table in tests.
using EnvFn = std::function<const char*(const char*)>;

/// Fails with one line when `runtime_name` (xrGetInstanceProperties' runtimeName) is known not to start a
/// compositor in this environment.
Status check_runtime_can_start(const std::string& runtime_name, const EnvFn& env);

}  // namespace lungar::platform::openxr
