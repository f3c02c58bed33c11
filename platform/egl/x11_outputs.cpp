/// @file x11_outputs.cpp
/// @brief RandR 1.5 monitors: XRRGetMonitors lists every active output under its own name, plus user-defined
/// monitors, with their position in the screen, which is all a full-screen window needs.
#include "platform/egl/x11_outputs.h"

#include <X11/Xlib.h>
#include <X11/extensions/Xrandr.h>

namespace lungar::platform {

Result<std::vector<ScreenArea>> x11_monitors(Display* display) {
  int event_base = 0, error_base = 0, major = 0, minor = 0;
  if (!XRRQueryExtension(display, &event_base, &error_base) || !XRRQueryVersion(display, &major, &minor) ||
      major * 100 + minor < 105) {
    return fail("the X server has no RandR 1.5 (needed to find an output by name)");
  }
  int count = 0;
  XRRMonitorInfo* monitors = XRRGetMonitors(display, DefaultRootWindow(display), True, &count);
  if (monitors == nullptr) return fail("the X server listed no monitors (XRRGetMonitors)");
  std::vector<ScreenArea> areas;
  for (int i = 0; i < count; ++i) {
    ScreenArea a;
    if (char* name = XGetAtomName(display, monitors[i].name)) {
      a.name = name;
      XFree(name);
    }
    a.x = monitors[i].x;
    a.y = monitors[i].y;
    a.width = monitors[i].width;
    a.height = monitors[i].height;
    areas.push_back(a);
  }
  XRRFreeMonitors(monitors);
  return areas;
}

Result<ScreenArea> find_x11_output(Display* display, const std::string& name) {
  auto areas = x11_monitors(display);
  if (!areas) return fail("X output '" + name + "': " + areas.error());
  std::string known;
  for (const ScreenArea& a : *areas) {
    if (a.name == name) return a;
    known += (known.empty() ? "" : ", ") + a.name;
  }
  return fail("X output '" + name + "': expected one of the active outputs (" +
                                               (known.empty() ? std::string("none") : known) + ")");
}

}  // namespace lungar::platform
