/// @file open_output.cpp
/// @brief display.output -> a FrameOutput.
#include "platform/output/open_output.h"

#include <cstdlib>

#include "platform/output/headless_output.h"
#include "platform/output/openxr_frame_output.h"
#include "platform/output/window_output.h"

namespace lungar::platform {

Result<std::unique_ptr<FrameOutput>> open_output(const config::Settings& s,
                                                 const std::function<void(const std::string&)>& log) {
  using config::Output;
  Output kind = s.display.output;
  const char* display = std::getenv("DISPLAY");
  if (kind == Output::Auto) kind = (display != nullptr && *display != '\0') ? Output::Window : Output::Headless;
  if (kind == Output::OpenXr) {
    auto xr = OpenXrFrameOutput::create(s, log);
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
