/// @file xr_frame_loop.h
/// @brief Test helpers around OpenXrOutput: a headless EGL context, the output on the test runtime, and a loop that
/// pumps frames (wait, then end with nothing drawn) until a condition holds.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "platform/egl/egl_context.h"
#include "platform/openxr/openxr_output.h"

namespace lungar::test {

struct XrRig {
  std::unique_ptr<platform::EglContext> context;
  std::unique_ptr<platform::openxr::OpenXrOutput> output;
  std::vector<std::string> lines;  ///< what the output logged
};

/// A headless context and the output on it (fails the test with the error line when either cannot be made).
/// The rig is returned by pointer so that the log sink's captured address stays valid.
std::unique_ptr<XrRig> make_rig(platform::openxr::OpenXrOptions options);

/// Pumps up to `max_loops` frames, submitting nothing, until `done()`; false (with a test failure naming the
/// error) when a call fails.
bool pump_until(platform::openxr::OpenXrOutput& output, const std::function<bool()>& done, int max_loops);

}  // namespace lungar::test
