/// @file open_output.cpp
/// @brief display.output -> a FrameOutput.
#include "platform/app/open_output.h"

#include <cstdlib>

#include "platform/output/headless_output.h"
#include "platform/output/openxr_frame_output.h"
#include "platform/output/window_output.h"
#include "platform/runtime/gl_math.h"
#include "platform/runtime/patient_force.h"

namespace lungar::platform {

glm::mat4 xr_world_from_space(const RegistrationSettings& r) {
  return to_glm(registration_isometry(r.xr_space_translation_mm, r.xr_space_rotation_wxyz));
}

Result<std::unique_ptr<FrameOutput>> open_output(const Settings& s,
                                                 const std::function<void(const std::string&)>& log) {
  Output kind = s.display.output;
  const char* display = std::getenv("DISPLAY");
  if (kind == Output::Auto) kind = (display != nullptr && *display != '\0') ? Output::Window : Output::Headless;
  if (kind == Output::OpenXr) {
    auto xr = OpenXrFrameOutput::create(s.display, s.hmd, xr_world_from_space(s.registration), log);
    if (!xr) return xr.with_context("");
    return std::unique_ptr<FrameOutput>(xr.take());
  }
  if (kind == Output::Window || kind == Output::Fullscreen) {
    auto window = WindowOutput::create(s.display, s.hmd);
    if (window) return std::unique_ptr<FrameOutput>(window.take());
    if (s.display.output != Output::Auto) return window.with_context("");
    log("no window (" + window.error() + "); running headless");
  }
  auto headless = HeadlessOutput::create(s.hmd, nullptr, s.display.max_fps);
  if (!headless) return headless.with_context("");
  return std::unique_ptr<FrameOutput>(headless.take());
}

}  // namespace lungar::platform
