/// @file output_check.cpp
/// @brief The output check: what display.output needs (an X display, the HMD's X output, an OpenXR runtime).
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "platform/doctor/checks.h"
#include "platform/egl/x11_outputs.h"

#include <X11/Xlib.h>  // last: it defines Status, which lungar's headers use as a type name

namespace lungar::platform::doctor {

namespace {

struct DisplayCloser {
  void operator()(Display* d) const { XCloseDisplay(d); }
};
using DisplayPtr = std::unique_ptr<Display, DisplayCloser>;

/// XOpenDisplay, tried three times 50 ms apart: Xvfb was seen refusing one connection in a few right after a
/// client closed its own, and a check should not fail on that.
DisplayPtr open_display(const std::string& name) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (Display* d = XOpenDisplay(name.c_str())) return DisplayPtr(d);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return nullptr;
}

const char* const kNoDisplayFix =
    "start lungar from the trainer's desktop session (the user unit does), or export DISPLAY=:0";

Check fullscreen_on_output(Display* x, const DisplaySettings& d) {
  if (d.x11_output.empty()) {
    return passed("output", "full screen at " + std::to_string(d.x_px) + "," + std::to_string(d.y_px) + " " +
                                std::to_string(d.width_px) + "x" + std::to_string(d.height_px) + " (no x11_output)");
  }
  auto area = find_x11_output(x, d.x11_output);
  if (!area) {
    return failed("output", "display.x11_output: " + area.error(),
                  "connect the HMD and switch its output on beside the desktop (xrandr --output " + d.x11_output +
                      " --auto --right-of PRIMARY), or set display.x11_output to a name from "
                      "`xrandr --listmonitors`");
  }
  return passed("output", "full screen on " + area->name + " at " + std::to_string(area->x) + "," +
                              std::to_string(area->y) + " " + std::to_string(area->width) + "x" +
                              std::to_string(area->height));
}

}  // namespace

Check check_output(const Settings& s, const DoctorEnv& env) {
  const Output out = s.display.output;
  if (out == Output::Headless) return passed("output", "headless (display.output = \"headless\"): no display needed");
  if (out == Output::OpenXr) return check_openxr_runtime(env);  // the runtime owns the display
  if (out == Output::Auto && env.display.empty()) {
    return passed("output", "auto: no DISPLAY, so the runtime draws headless");
  }
  const std::string what = std::string("display.output = \"") + to_string(out) + "\"";
  if (env.display.empty()) return failed("output", what + " needs an X display, and DISPLAY is not set", kNoDisplayFix);
  DisplayPtr x = open_display(env.display);
  if (!x) {
    const std::string detail = "cannot open the X display '" + env.display + "'";
    const std::string fix = "run as the user logged in on that display, or allow this user: xhost +SI:localuser:$USER";
    if (out == Output::Auto) return warned("output", detail + "; the runtime falls back to headless", fix);
    return failed("output", what + ": " + detail, fix);
  }
  if (out == Output::Fullscreen) return fullscreen_on_output(x.get(), s.display);
  return passed("output", "a window on X display " + env.display);
}

}  // namespace lungar::platform::doctor
