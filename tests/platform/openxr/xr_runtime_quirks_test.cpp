/// @file xr_runtime_quirks_test.cpp
/// @brief Monado with nowhere to show frames is refused with one line; with a display, direct mode or its null
/// compositor it is let through, and other runtimes always are. Against the real Monado too: no crash.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <string>

#include "platform/egl/egl_context.h"
#include "platform/openxr/openxr_output.h"
#include "platform/openxr/xr_runtime_quirks.h"
#include "tests/platform/openxr/xr_test_runtime.h"

namespace lungar::platform::openxr {
namespace {

const std::string kMonado = "Monado(XRT) by Collabora et al 'v25.0.0' 25.0.0";

Status check(const std::string& runtime, const std::map<std::string, std::string>& vars) {
  return check_runtime_can_start(runtime, [&](const char* name) -> const char* {
    auto it = vars.find(name);
    return it == vars.end() ? nullptr : it->second.c_str();
  });
}

TEST(XrRuntimeQuirks, MonadoWithNowhereToShowFramesIsRefused) {
  const Status s = check(kMonado, {{"DISPLAY", ""}});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().find("XRT_COMPOSITOR_NULL=1"), std::string::npos) << s.error();
  EXPECT_NE(s.error().find("DISPLAY"), std::string::npos) << s.error();
  EXPECT_EQ(s.error().find('\n'), std::string::npos);
}

TEST(XrRuntimeQuirks, MonadoWithADisplayDirectModeOrNullCompositorStarts) {
  EXPECT_TRUE(check(kMonado, {{"DISPLAY", ":0"}}));
  EXPECT_TRUE(check(kMonado, {{"WAYLAND_DISPLAY", "wayland-0"}}));
  EXPECT_TRUE(check(kMonado, {{"XRT_COMPOSITOR_NULL", "1"}}));
  EXPECT_TRUE(check(kMonado, {{"XRT_COMPOSITOR_FORCE_VK_DISPLAY", "0"}}));
}

TEST(XrRuntimeQuirks, OtherRuntimesAreNotSecondGuessed) {
  EXPECT_TRUE(check("SteamVR/OpenXR", {}));
}

TEST(XrRuntimeQuirks, RealMonadoWithoutADisplayGivesOneLineNotACrash) {
  ASSERT_FALSE(test::use_test_runtime(test::SimulatedHead::Fixed).empty());
  unsetenv("XRT_COMPOSITOR_NULL");
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  auto context = EglContext::headless();
  ASSERT_TRUE(context) << context.error();
  auto output = OpenXrOutput::create(**context, {});
  ASSERT_FALSE(output);
  EXPECT_NE(output.error().find("XRT_COMPOSITOR_NULL=1"), std::string::npos) << output.error();
}

}  // namespace
}  // namespace lungar::platform::openxr
