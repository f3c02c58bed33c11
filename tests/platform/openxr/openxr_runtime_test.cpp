/// @file openxr_runtime_test.cpp
/// @brief The Runtime on the OpenXR output (display.output = "openxr") against Monado: a run writes its stats
/// (with the xr_* keys) and a snapshot of both views; no runtime stops lungar with one line and no files; the
/// head comes from the runtime, placed in the world by the registration (by default where the window output's
/// viewer stands), or from lungar's tracker with the runtime's eye offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "drivers/mock/mock_trajectory.h"
#include "drivers/tracker/tracker_config.h"
#include "platform/app/open_output.h"
#include "platform/app/run.h"
#include "platform/openxr/xr_view_math.h"
#include "platform/output/openxr_frame_output.h"
#include "tests/platform/openxr/xr_test_runtime.h"

namespace lungar::test {
namespace {

const std::string kData = std::string(LUNGAR_SOURCE_DIR) + "/tests/data/";

class OpenXrRuntime : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(testing::TempDir()) /
           ("lungar_openxr_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    settings_.sim.asset = kData + "hil_lungs.lungbake";
    settings_.display.output = platform::Output::OpenXr;
    settings_.trackers().mock.trajectory = "static";
    options_.frames = 30;
    options_.snapshot_path = (dir_ / "shot.png").string();
    options_.stats_json_path = (dir_ / "stats.json").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  platform::Settings settings_;
  platform::RuntimeOptions options_;
};

TEST_F(OpenXrRuntime, RunWritesTheXrStatsAndASnapshot) {
  ASSERT_FALSE(use_test_runtime(SimulatedHead::Fixed).empty());
  ASSERT_EQ(platform::run_runtime(settings_, options_), 0);
  std::ifstream in(options_.stats_json_path);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["frames"], 30);
  EXPECT_EQ(j["xr_frames_submitted"], 30);  // every frame the runtime showed; none lost
  EXPECT_NE(j["xr_runtime"].get<std::string>().find("Monado"), std::string::npos) << j["xr_runtime"];
  EXPECT_DOUBLE_EQ(j["xr_predicted_display_period_ms"].get<double>(), 50.0);  // the null compositor's 20 Hz
  EXPECT_NEAR(j["fps_median"].get<double>(), 20.0, 2.0);                      // xrWaitFrame paces the loop
  EXPECT_TRUE(std::filesystem::exists(options_.snapshot_path));
  EXPECT_GT(std::filesystem::file_size(options_.snapshot_path), 2000u);
}

TEST_F(OpenXrRuntime, NoRuntimeStopsLungarWithOneLineAndNoFiles) {
  setenv("XR_RUNTIME_JSON", (dir_ / "missing.json").c_str(), 1);
  testing::internal::CaptureStderr();
  const int code = platform::run_runtime(settings_, options_);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, 1);
  std::istringstream lines(err);
  int errors = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.find("error:") == std::string::npos) continue;
    ++errors;
    EXPECT_NE(line.find("XR_RUNTIME_JSON=" + (dir_ / "missing.json").string()), std::string::npos) << line;
    EXPECT_NE(line.find("-51"), std::string::npos) << line;
    EXPECT_NE(line.find("display.output = \"openxr\""), std::string::npos) << line;
  }
  EXPECT_EQ(errors, 1) << err;
  EXPECT_FALSE(std::filesystem::exists(options_.stats_json_path));
  EXPECT_FALSE(std::filesystem::exists(options_.snapshot_path));
}

/// Frames until the output gives located views; the views of that frame, with `head` passed as lungar's head.
platform::FrameViews first_views(platform::OpenXrFrameOutput& out, const glm::mat4& head) {
  for (int i = 0; i < 100; ++i) {
    auto timing = out.begin_frame(lungar::monotonic_ns());
    EXPECT_TRUE(timing) << timing.error();
    if (!timing) break;
    platform::FrameViews views = out.views(head);
    EXPECT_TRUE(out.end_frame());
    if (views.count == 2) return views;
  }
  ADD_FAILURE() << "no located views in 100 frames";
  return {};
}

glm::vec3 eye_position(const render::EyeView& e) { return glm::vec3(glm::inverse(e.view)[3]); }
glm::vec3 eye_ahead(const render::EyeView& e) { return -glm::vec3(glm::inverse(e.view)[2]); }

TEST_F(OpenXrRuntime, DefaultRegistrationPutsTheRuntimesHeadWhereTheDefaultViewerStands) {
  ASSERT_FALSE(use_test_runtime(SimulatedHead::Fixed).empty());  // the remote HMD stays at LOCAL's origin
  auto out = platform::OpenXrFrameOutput::create(settings_.display, settings_.hmd, platform::xr_world_from_space(settings_.registration), nullptr);
  ASSERT_TRUE(out) << out.error();
  // lungar's own head pose is ignored with head = "openxr": any matrix gives the same views.
  const glm::mat4 far_away = glm::translate(glm::mat4(1.f), glm::vec3(5000.f, 0.f, 0.f));
  const platform::FrameViews views = first_views(**out, far_away);
  ASSERT_EQ(views.count, 2u);
  // The window output's default viewer: the mock's static head sensor, looking at the patient, with the eyes
  // at hmd.head_to_eye_mm in the sensor's frame.
  auto sensor = drivers::mock_pose("static", drivers::Role::Head, 0.0);
  ASSERT_TRUE(sensor);
  const auto& q = sensor->orientation_wxyz;
  const glm::quat sensor_rotation(static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2]),
                                  static_cast<float>(q[3]));
  const glm::vec3 sensor_position(sensor->position_mm[0], sensor->position_mm[1], sensor->position_mm[2]);
  const auto& offset = settings_.hmd.head_to_eye_mm;
  const glm::vec3 default_eyes = sensor_position + sensor_rotation * glm::vec3(offset[0], offset[1], offset[2]);
  const glm::vec3 centre = 0.5f * (eye_position(views.eyes[0]) + eye_position(views.eyes[1]));
  EXPECT_NEAR(glm::length(centre - default_eyes), 0.f, 1.f);
  // Looking where the sensor looks (its +y): at the mock patient's centre, about 0.8 m ahead.
  const glm::vec3 sensor_ahead = sensor_rotation * glm::vec3(0.f, 1.f, 0.f);
  EXPECT_NEAR(glm::length(eye_ahead(views.eyes[0]) - sensor_ahead), 0.f, 1e-3f);
  const auto& c = drivers::kMockPatientCentreMm;
  const glm::vec3 to_patient = glm::normalize(glm::vec3(c[0], c[1], c[2]) - sensor_position);
  EXPECT_NEAR(glm::length(sensor_ahead - to_patient), 0.f, 1e-3f);
  // The eyes are the runtime's IPD apart (64 mm as the remote HMD locates them).
  EXPECT_NEAR(glm::length(eye_position(views.eyes[1]) - eye_position(views.eyes[0])), 64.f, 2.f);
}

TEST_F(OpenXrRuntime, TrackerHeadPlacesTheRuntimesEyeOffsetsOnLungarsHead) {
  ASSERT_FALSE(use_test_runtime(SimulatedHead::Fixed).empty());
  settings_.display.openxr.head = platform::XrHead::Tracker;
  auto out = platform::OpenXrFrameOutput::create(settings_.display, settings_.hmd, platform::xr_world_from_space(settings_.registration), nullptr);
  ASSERT_TRUE(out) << out.error();
  const glm::mat4 head = glm::rotate(glm::translate(glm::mat4(1.f), glm::vec3(100.f, -900.f, 1200.f)),
                                     glm::radians(70.f), glm::vec3(1.f, 0.f, 0.f));
  const platform::FrameViews views = first_views(**out, head);
  ASSERT_EQ(views.count, 2u);
  for (std::size_t v = 0; v < 2; ++v) {
    // Each eye is where the runtime puts it relative to its own head (the VIEW space), on lungar's head.
    const glm::vec3 offset(v == 0 ? -32.f : 32.f, 0.f, 0.f);  // the remote HMD's eyes, as located
    const glm::vec3 expected(head * glm::vec4(offset, 1.f));
    EXPECT_NEAR(glm::length(eye_position(views.eyes[v]) - expected), 0.f, 1.f) << "view " << v;
    EXPECT_NEAR(glm::length(eye_ahead(views.eyes[v]) - glm::vec3(head * glm::vec4(0.f, 0.f, -1.f, 0.f))), 0.f, 1e-3f);
  }
}

}  // namespace
}  // namespace lungar::test
