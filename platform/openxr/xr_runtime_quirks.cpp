/// @file xr_runtime_quirks.cpp
/// @brief Monado without a display.
#include "platform/openxr/xr_runtime_quirks.h"

namespace lungar::platform::openxr {
namespace {

bool set(const EnvFn& env, const char* name) {
  const char* v = env(name);
  return v != nullptr && *v != '\0';
}

}  // namespace

Status check_runtime_can_start(const std::string& runtime_name, const EnvFn& env) {
  if (runtime_name.rfind("Monado", 0) != 0) return ok();
  // Where Monado's compositor can show frames: an X or Wayland display, the headset itself through Vulkan's
  // VK_KHR_display or NVIDIA's direct mode, or nowhere on purpose (the null compositor).
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "XRT_COMPOSITOR_NULL", "XRT_COMPOSITOR_FORCE_VK_DISPLAY",
                           "XRT_COMPOSITOR_FORCE_NVIDIA"}) {
    if (set(env, name)) return ok();
  }
  return fail("OpenXR: " + runtime_name +
              ": expected a display for its compositor (DISPLAY or WAYLAND_DISPLAY, or "
              "XRT_COMPOSITOR_FORCE_VK_DISPLAY for direct mode), or XRT_COMPOSITOR_NULL=1 for none; without one, "
              "Monado fails to start its compositor and crashes the process");
}

}  // namespace lungar::platform::openxr
