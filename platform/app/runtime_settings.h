/// @file runtime_settings.h
/// @brief The settings a Runtime is told (RuntimeConfig), taken from the whole tree: the one place that knows both.
/// @ingroup platform
#pragma once

#include "platform/app/settings.h"
#include "platform/runtime/runtime_config.h"

namespace lungar::platform {

/// [render], [hmd] (view, eye offset, prediction), [registration] and [sim] as the frame uses them, with the demo's
/// static scene (patient ahead, head in front) as the poses drawn before a tracker delivers one.
RuntimeConfig runtime_config(const Settings& s);

}  // namespace lungar::platform
