/// @file xr_error.h
/// @brief OpenXR results as lungar's one error line: which call failed, the result's name and number, and for the
/// loader's "no runtime" the variable that names one.
#pragma once

#include <string>

#include "platform/openxr/xr_headers.h"

namespace lungar::platform::openxr {

/// "OpenXR: xrCreateSession: XR_ERROR_GRAPHICS_DEVICE_INVALID (-38)"; the name comes from the runtime when an
/// instance is given, else from a short table of the results a call can give before there is one.
std::string xr_error(XrInstance instance, const char* call, XrResult result);

/// The line for XR_ERROR_RUNTIME_UNAVAILABLE (-51): the loader found no runtime, and XR_RUNTIME_JSON is how to
/// name one (what it was set to, if anything, is part of the line).
std::string runtime_unavailable_error(const char* call);

}  // namespace lungar::platform::openxr
