/// @file xr_error.cpp
/// @brief Names of OpenXR results, and the missing-runtime line.
#include "platform/openxr/xr_error.h"

#include <cstdio>
#include <cstdlib>

namespace lungar::platform::openxr {
namespace {

// The results xrEnumerateInstanceExtensionProperties and xrCreateInstance give when there is no instance to ask.
const char* loader_result_name(XrResult r) {
  switch (r) {
    case XR_ERROR_RUNTIME_UNAVAILABLE: return "XR_ERROR_RUNTIME_UNAVAILABLE";
    case XR_ERROR_RUNTIME_FAILURE: return "XR_ERROR_RUNTIME_FAILURE";
    case XR_ERROR_EXTENSION_NOT_PRESENT: return "XR_ERROR_EXTENSION_NOT_PRESENT";
    case XR_ERROR_API_VERSION_UNSUPPORTED: return "XR_ERROR_API_VERSION_UNSUPPORTED";
    case XR_ERROR_INITIALIZATION_FAILED: return "XR_ERROR_INITIALIZATION_FAILED";
    case XR_ERROR_API_LAYER_NOT_PRESENT: return "XR_ERROR_API_LAYER_NOT_PRESENT";
    case XR_ERROR_OUT_OF_MEMORY: return "XR_ERROR_OUT_OF_MEMORY";
    case XR_ERROR_VALIDATION_FAILURE: return "XR_ERROR_VALIDATION_FAILURE";
    case XR_ERROR_NAME_INVALID: return "XR_ERROR_NAME_INVALID";
    default: return "XrResult";
  }
}

}  // namespace

std::string xr_error(XrInstance instance, const char* call, XrResult result) {
  if (result == XR_ERROR_RUNTIME_UNAVAILABLE) return runtime_unavailable_error(call);
  char name[XR_MAX_RESULT_STRING_SIZE] = {};
  if (instance == XR_NULL_HANDLE || xrResultToString(instance, result, name) != XR_SUCCESS) {
    std::snprintf(name, sizeof name, "%s", loader_result_name(result));
  }
  return std::string("OpenXR: ") + call + ": " + name + " (" + std::to_string(static_cast<int>(result)) + ")";
}

std::string runtime_unavailable_error(const char* call) {
  const char* json = std::getenv("XR_RUNTIME_JSON");
  const std::string named = (json != nullptr && *json != '\0')
                                ? std::string("XR_RUNTIME_JSON=") + json + " did not load"
                                : std::string("XR_RUNTIME_JSON is not set and no active runtime is installed");
  return std::string("OpenXR: ") + call + ": no OpenXR runtime (XR_ERROR_RUNTIME_UNAVAILABLE, -51): " + named +
         "; expected XR_RUNTIME_JSON to name a runtime's manifest (scripts/setup-openxr builds Monado and prints "
         "its manifest)";
}

}  // namespace lungar::platform::openxr
