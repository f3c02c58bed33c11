/// @file open_output.h
/// @brief The output the settings ask for: display.output = window | fullscreen | headless | openxr | auto (a
/// window when a display is there, else headless). The one place that chooses an output; a new kind of output is
/// one more case here.
/// @ingroup platform
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <glm/mat4x4.hpp>

#include "platform/app/settings.h"
#include "platform/runtime/frame_output.h"

namespace lungar::platform {

/// Opens the output and makes its GL context current on this thread. `log` hears a fallback (auto: no window).
Result<std::unique_ptr<FrameOutput>> open_output(const Settings& settings,
                                                 const std::function<void(const std::string&)>& log);

/// The OpenXR reference space's pose in the tracker world, from [registration] xr_space_*.
glm::mat4 xr_world_from_space(const RegistrationSettings& r);

}  // namespace lungar::platform
