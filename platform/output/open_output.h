/// @file open_output.h
/// @brief The output the settings ask for: display.output = window | fullscreen | headless | openxr | auto (a
/// window when a display is there, else headless). The one place that chooses an output; a new kind of output is
/// one more case here.
/// @ingroup platform
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "config/settings.h"
#include "platform/runtime/frame_output.h"

namespace lungar::platform {

/// Opens the output and makes its GL context current on this thread. `log` hears a fallback (auto: no window).
Result<std::unique_ptr<FrameOutput>> open_output(const config::Settings& settings,
                                                 const std::function<void(const std::string&)>& log);

}  // namespace lungar::platform
