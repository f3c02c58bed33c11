/// @file xr_instance.h
/// @brief The OpenXR instance and its head-mounted system: the loader finds the runtime (XR_RUNTIME_JSON or the
/// active runtime), lungar asks for XR_MNDX_egl_enable (its GLES context through EGL) and, where the runtime has
/// them, the depth layer and the timespec clock; the system's stereo views give the swapchain sizes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "config/base/unique_handle.h"
#include "platform/openxr/xr_headers.h"

namespace lungar::platform::openxr {

struct InstanceOptions {
  std::string application = "lungar";
  /// XR_MND_headless instead of a graphics binding: a session with no swapchains (the lifecycle tests, which also
  /// run under the validation layer; bookworm's layer rejects the EGL binding).
  bool headless = false;
  std::vector<std::string> api_layers;  ///< e.g. "XR_APILAYER_LUNARG_core_validation"
};

/// Who runs the headset, for logs and the stats JSON.
struct RuntimeInfo {
  std::string name;         ///< xrGetInstanceProperties' runtimeName, e.g. "Monado(XRT) by Collabora et al ..."
  std::string version;      ///< "25.0.0"
  std::string system_name;  ///< xrGetSystemProperties' systemName, e.g. "Monado: Simulated HMD"
  std::string text() const { return name + " " + version; }
};

class Instance {
 public:
  /// Loads the runtime and picks its head-mounted system. No runtime: one line naming XR_RUNTIME_JSON.
  static Result<Instance> create(const InstanceOptions& options);

  XrInstance handle() const { return instance_.get(); }
  XrSystemId system() const { return system_; }
  const RuntimeInfo& runtime() const { return runtime_; }
  bool headless() const { return headless_; }
  /// XR_KHR_composition_layer_depth was offered and enabled: depth swapchains go with the projection layer.
  bool depth_layer() const { return depth_layer_; }
  /// The primary stereo configuration's views (recommended and largest image sizes), one per eye.
  const std::vector<XrViewConfigurationView>& views() const { return views_; }
  static constexpr XrViewConfigurationType kViewConfiguration = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;

  /// XrTime <-> CLOCK_MONOTONIC nanoseconds (XR_KHR_convert_timespec_time; without it, the runtime's time is
  /// taken to be the monotonic clock, as it is in Monado).
  std::int64_t to_monotonic_ns(XrTime time) const;
  XrTime from_monotonic_ns(std::int64_t ns) const;

  /// Looks up an extension function; an error line names it when the runtime has none.
  Result<PFN_xrVoidFunction> function(const char* name) const;

 private:
  Instance() = default;
  Status pick_system();
  UniqueHandle<XrInstance, xrDestroyInstance> instance_;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  RuntimeInfo runtime_;
  bool headless_ = false;
  bool depth_layer_ = false;
  PFN_xrConvertTimeToTimespecTimeKHR to_timespec_ = nullptr;
  PFN_xrConvertTimespecTimeToTimeKHR from_timespec_ = nullptr;
  std::vector<XrViewConfigurationView> views_;
};

}  // namespace lungar::platform::openxr
