/// @file x11_outputs.h
/// @brief Where an X output is: the RandR monitors of an X screen (each active output, e.g. "HDMI-1", and any set
/// with `xrandr --setmonitor`), so that a full-screen window can cover an HMD's output in extended mode.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"

typedef struct _XDisplay Display;  // NOLINT: Xlib's own spelling, so that this header needs no Xlib.h

namespace lungar::platform {

struct ScreenArea {
  std::string name;  ///< the output's (or monitor's) name, as `xrandr --listmonitors` prints it
  int x = 0, y = 0, width = 0, height = 0;  ///< pixels in the X screen
};

/// The active monitors of the default screen of `display`; an error when the server has no RandR 1.5.
Result<std::vector<ScreenArea>> x11_monitors(Display* display);

/// The monitor called `name`; an error naming it and listing the ones there are.
Result<ScreenArea> find_x11_output(Display* display, const std::string& name);

}  // namespace lungar::platform
