/// @file openxr_session_test.cpp
/// @brief The session's life against Monado: READY -> SYNCHRONIZED -> VISIBLE -> FOCUSED with lungar's EGL context
/// bound through XR_MNDX_egl_enable, then a clean exit (STOPPING -> IDLE -> EXITING) when lungar asks; a headless
/// session under the OpenXR validation layer; and the missing-runtime error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "platform/openxr/xr_instance.h"
#include "tests/platform/openxr/xr_frame_loop.h"
#include "tests/platform/openxr/xr_test_runtime.h"

namespace lungar::test {
namespace {

using platform::openxr::OpenXrOptions;

// The position in `lines` of the first line at or after `from` containing `text` (lines.size() when none does).
std::size_t line_index(const std::vector<std::string>& lines, const std::string& text, std::size_t from = 0) {
  for (std::size_t i = from; i < lines.size(); ++i) {
    if (lines[i].find(text) != std::string::npos) return i;
  }
  return lines.size();
}

// 20 Hz null compositor: 200 loops are 10 s at most; FOCUSED comes within a few frames.
constexpr int kMaxLoops = 200;

TEST(OpenXrSession, ReachesFocusedThenExitsCleanlyWhenAsked) {
  ASSERT_FALSE(use_test_runtime(SimulatedHead::Fixed).empty());
  auto rig = make_rig(OpenXrOptions{});
  ASSERT_TRUE(rig);
  auto& out = *rig->output;
  EXPECT_NE(out.runtime().name.find("Monado"), std::string::npos) << out.runtime().name;
  EXPECT_FALSE(out.runtime().version.empty());
  ASSERT_TRUE(pump_until(out, [&] { return out.lifecycle().reached(XR_SESSION_STATE_FOCUSED); }, kMaxLoops));
  EXPECT_TRUE(out.lifecycle().running());
  EXPECT_GT(out.predicted_display_period_ms(), 0.0);

  ASSERT_TRUE(out.request_exit());
  ASSERT_TRUE(pump_until(out, [&] { return out.exited(); }, kMaxLoops));
  EXPECT_FALSE(out.lifecycle().running());
  // Every state, in OpenXR's order, one line each.
  const char* order[] = {"session READY", "session SYNCHRONIZED", "session VISIBLE", "session FOCUSED",
                         "session STOPPING", "session IDLE", "session EXITING"};
  std::size_t at = 0;
  for (const char* state : order) {
    at = line_index(rig->lines, state, at);
    ASSERT_LT(at, rig->lines.size()) << "no line for " << state << " in order";
  }
  EXPECT_NE(rig->lines[line_index(rig->lines, "STOPPING")].find("lungar asked to exit"), std::string::npos);
  // After EXITING, nothing more is waited for: the loop ends.
  auto after = out.wait_frame();
  ASSERT_TRUE(after) << after.error();
  EXPECT_FALSE(after->begun);
}

TEST(OpenXrSession, HeadlessSessionPassesTheValidationLayer) {
  ASSERT_FALSE(use_test_runtime(SimulatedHead::Fixed).empty());
  // Bookworm's core validation layer does not know XR_MNDX_egl_enable's binding, so it checks a headless session
  // (XR_MND_headless): the same lifecycle calls, frames with no layers. It writes what it finds to a file.
  const std::string report = testing::TempDir() + "openxr_validation.txt";
  std::remove(report.c_str());
  setenv("XR_CORE_VALIDATION_EXPORT_TYPE", "text", 1);
  setenv("XR_CORE_VALIDATION_FILE_NAME", report.c_str(), 1);
  OpenXrOptions options;
  options.instance.headless = true;
  options.instance.api_layers = {"XR_APILAYER_LUNARG_core_validation"};
  auto rig = make_rig(options);
  ASSERT_TRUE(rig);
  auto& out = *rig->output;
  ASSERT_TRUE(pump_until(out, [&] { return out.lifecycle().reached(XR_SESSION_STATE_FOCUSED); }, kMaxLoops));
  ASSERT_TRUE(out.request_exit());
  ASSERT_TRUE(pump_until(out, [&] { return out.exited(); }, kMaxLoops));
  rig.reset();  // the instance goes, and the layer with it
  std::ifstream in(report);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str().find("VALID_ERROR"), std::string::npos) << text.str();
}

TEST(OpenXrSession, NoRuntimeIsOneLineNamingXrRuntimeJson) {
  const std::string missing = testing::TempDir() + "no-such-runtime/openxr_monado.json";
  setenv("XR_RUNTIME_JSON", missing.c_str(), 1);
  auto instance = platform::openxr::Instance::create({});
  ASSERT_FALSE(instance);
  const std::string& e = instance.error();
  EXPECT_NE(e.find("XR_RUNTIME_JSON=" + missing), std::string::npos) << e;
  EXPECT_NE(e.find("XR_ERROR_RUNTIME_UNAVAILABLE, -51"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;

  // The whole output fails the same way, with no crash and nothing half made.
  auto context = platform::EglContext::headless();
  ASSERT_TRUE(context) << context.error();
  auto output = platform::openxr::OpenXrOutput::create(**context, {});
  ASSERT_FALSE(output);
  EXPECT_EQ(output.error(), e);
}

}  // namespace
}  // namespace lungar::test
