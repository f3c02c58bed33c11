/// @file xr_frame_loop.cpp
/// @brief The OpenXR test rig and frame pump.
#include "tests/platform/openxr/xr_frame_loop.h"

#include <gtest/gtest.h>

namespace lungar::test {

std::unique_ptr<XrRig> make_rig(platform::openxr::OpenXrOptions options) {
  auto rig = std::make_unique<XrRig>();
  auto context = platform::EglContext::headless();
  if (!context) {
    ADD_FAILURE() << context.error();
    return nullptr;
  }
  rig->context = context.take();
  std::vector<std::string>* lines = &rig->lines;
  options.log = [lines](const std::string& line) { lines->push_back(line); };
  auto output = platform::openxr::OpenXrOutput::create(*rig->context, options);
  if (!output) {
    ADD_FAILURE() << output.error();
    return nullptr;
  }
  rig->output = output.take();
  return rig;
}

bool pump_until(platform::openxr::OpenXrOutput& output, const std::function<bool()>& done, int max_loops) {
  for (int i = 0; i < max_loops && !done(); ++i) {
    auto timing = output.wait_frame();
    if (!timing) {
      ADD_FAILURE() << timing.error();
      return false;
    }
    if (auto ended = output.end_frame(); !ended) {
      ADD_FAILURE() << ended.error();
      return false;
    }
  }
  return done();
}

}  // namespace lungar::test
