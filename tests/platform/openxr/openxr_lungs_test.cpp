/// @file openxr_lungs_test.cpp
/// @brief The deformed lungs in both views of Monado's simulated headset, read back from the swapchain images: the
/// lungs' pixels lie where each view's located pose and field of view project the shader's deformed points, the
/// two views differ by the parallax of their poses, 120 frames are submitted, and the simulated head's motion moves
/// the picture (a fixed head keeps it still).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "platform/openxr/xr_view_math.h"
#include "render/lung_drawable.h"
#include "render/renderer.h"
#include "tests/platform/openxr/xr_frame_loop.h"
#include "tests/platform/openxr/xr_test_runtime.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::test {
namespace {

using platform::openxr::OpenXrOptions;

/// A pixel rectangle; x right, y down (the image's rows top first).
struct Box {
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
  void add(float x, float y) {
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
  }
  bool empty() const { return x1 < x0; }
  float cx() const { return 0.5f * (x0 + x1); }
  float cy() const { return 0.5f * (y0 + y1); }
};

std::ostream& operator<<(std::ostream& os, const Box& b) {
  return os << "[" << b.x0 << ", " << b.y0 << " .. " << b.x1 << ", " << b.y1 << "]";
}

// Points are 5 px squares centred on their projection; the rasteriser rounds to pixel centres.
constexpr float kEdgeTolerancePx = 3.5f;
constexpr float kPointSizePx = 5.f;

/// The lit (non-background) pixels' bounding box of an RGBA image, top row first.
Box drawn_box(const std::vector<std::uint8_t>& rgba, int width, int height) {
  Box b;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      if (p[0] + p[1] + p[2] > 0) b.add(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    }
  }
  return b;
}

/// Where the runtime's located view (pose and field of view, straight from xrLocateViews) puts the points (lung
/// frame, mm, placed by `model` in the reference space): their bounding box in pixels, y down. Worked out here
/// from the angles, independently of the output's matrices: a point at tangents (tx, ty) in front of the eye is at
/// the fraction (tx - tan left) / (tan right - tan left) of the image's width, and likewise up to down.
Box projected_box(const std::vector<float>& xyz, const glm::mat4& model, const XrView& view, int width, int height) {
  const XrQuaternionf& q = view.pose.orientation;
  const glm::quat to_view = glm::inverse(glm::quat(q.w, q.x, q.y, q.z));
  const glm::vec3 eye(view.pose.position.x * 1000.f, view.pose.position.y * 1000.f, view.pose.position.z * 1000.f);
  const float l = std::tan(view.fov.angleLeft), r = std::tan(view.fov.angleRight);
  const float u = std::tan(view.fov.angleUp), d = std::tan(view.fov.angleDown);
  Box b;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
    const glm::vec3 p = to_view * (glm::vec3(model * glm::vec4(xyz[i], xyz[i + 1], xyz[i + 2], 1.f)) - eye);
    const float tx = p.x / -p.z, ty = p.y / -p.z;
    b.add((tx - l) / (r - l) * static_cast<float>(width), (u - ty) / (u - d) * static_cast<float>(height));
  }
  return b;
}

void expect_box_near(const Box& drawn, const Box& predicted, float tolerance, const char* what) {
  ASSERT_FALSE(drawn.empty()) << what << ": nothing drawn";
  // The drawn box is the points' box grown by half a point on each side.
  const float h = kPointSizePx / 2;
  EXPECT_NEAR(drawn.x0, predicted.x0 - h, tolerance) << what << " drawn " << drawn << " predicted " << predicted;
  EXPECT_NEAR(drawn.x1, predicted.x1 + h, tolerance) << what << " drawn " << drawn << " predicted " << predicted;
  EXPECT_NEAR(drawn.y0, predicted.y0 - h, tolerance) << what << " drawn " << drawn << " predicted " << predicted;
  EXPECT_NEAR(drawn.y1, predicted.y1 + h, tolerance) << what << " drawn " << drawn << " predicted " << predicted;
}

class OpenXrLungs : public ::testing::Test {
 protected:
  /// Makes the rig and the lungs; the lungs stand upright 0.7 m ahead of where the head is at the first located
  /// frame, facing it.
  void start(SimulatedHead head) {
    ASSERT_FALSE(use_test_runtime(head).empty());
    OpenXrOptions options;
    options.near_mm = 100.f;
    options.far_mm = 3000.f;
    rig_ = make_rig(options);
    ASSERT_TRUE(rig_);
    asset_ = ellipsoid_pair(20000, 2, 7);
    set_local_transfer(asset_, 1.f);  // D = w A Y00 f00 dV: an even inflation along the normals
    auto d = render::LungDrawable::create(asset_);
    ASSERT_TRUE(d) << d.error();
    drawable_.emplace(d.take());
    auto r = render::Renderer::create(*drawable_);
    ASSERT_TRUE(r) << r.error();
    renderer_.emplace(r.take());
    force_ = {0.035f, 0.f, 0.f, 0.f};  // about 20 mm outward at 500 mL
    lungs_[0] = {force_, 0.f, {0.45f, 0.6f, 0.95f}};
    lungs_[1] = {force_, 0.f, {0.9f, 0.45f, 0.45f}};
  }

  /// One frame: wait, locate, draw both views, read them back, submit. False when the runtime did not ask for a
  /// picture this frame (then nothing is drawn or read).
  bool frame(float volume_change_ml) {
    auto& out = *rig_->output;
    auto timing = out.wait_frame();
    EXPECT_TRUE(timing) << timing.error();
    if (!timing || !timing->should_render) {
      EXPECT_TRUE(out.end_frame());
      return false;
    }
    auto eyes = out.locate_views();
    EXPECT_TRUE(eyes) << eyes.error();
    if (!eyes || eyes->size() != 2) {
      EXPECT_TRUE(out.end_frame());
      return false;
    }
    if (!model_) {  // place the lungs in front of the first located head
      const XrPosef& l = out.located()[0].pose;
      const XrPosef& r = out.located()[1].pose;
      const glm::mat4 head = platform::openxr::pose_matrix_mm(l);
      const glm::vec3 centre = 0.5f * (glm::vec3(platform::openxr::pose_matrix_mm(l)[3]) +
                                       glm::vec3(platform::openxr::pose_matrix_mm(r)[3]));
      const glm::vec3 ahead = -glm::vec3(head[2]);
      // LPS to the viewer's frame: superior is up (+y), posterior away from the viewer (-z), the patient's left on
      // the viewer's right: a -90 degree turn about x.
      model_ = glm::translate(glm::mat4(1.f), centre + 700.f * ahead) *
               glm::rotate(glm::mat4(1.f), glm::radians(-90.f), glm::vec3(1.f, 0.f, 0.f));
    }
    for (auto& l : lungs_) l.volume_change_ml = volume_change_ml;
    for (std::size_t v = 0; v < 2; ++v) {
      eyes_[v] = (*eyes)[v];
      EXPECT_TRUE(out.bind_view(v));
      render::FrameInputs in;
      in.lungs = lungs_;
      in.eyes = std::span<const render::EyeView>(&eyes_[v], 1);
      in.model = *model_;
      in.level_of_detail = false;    // every point, so that the silhouette is the points' hull
      in.cull_back_facing = false;
      in.point_size_px = kPointSizePx;
      const auto drawn = renderer_->draw(*drawable_, in);
      EXPECT_TRUE(drawn) << drawn.error();
      EXPECT_TRUE(out.read_view(v, images_[v]));
    }
    const auto captured = renderer_->capture_deformed(*drawable_, lungs_, deformed_);
    EXPECT_TRUE(captured) << captured.error();
    for (std::size_t v = 0; v < 2; ++v) located_[v] = out.located()[v];
    EXPECT_TRUE(out.end_frame());
    return true;
  }

  int width() const { return rig_->output->view_width(); }
  int height() const { return rig_->output->view_height(); }

  std::unique_ptr<XrRig> rig_;
  sim::BakedAsset asset_;
  std::optional<render::LungDrawable> drawable_;
  std::optional<render::Renderer> renderer_;
  std::vector<float> force_;
  render::LungFrame lungs_[2];
  std::optional<glm::mat4> model_;
  std::array<render::EyeView, 2> eyes_;
  std::array<XrView, 2> located_{};
  std::array<std::vector<std::uint8_t>, 2> images_;
  std::vector<float> deformed_;
};

TEST_F(OpenXrLungs, DeformedLungsLieWhereEachViewProjectsThemFor120Frames) {
  start(SimulatedHead::Fixed);
  ASSERT_FALSE(HasFatalFailure());
  auto& out = *rig_->output;
  int frames = 0;
  float largest_breath_shift = 0.f, smallest_parallax = 1e9f;
  for (int loop = 0; frames < 120 && loop < 400; ++loop) {
    const float dv = 250.f + 250.f * std::sin(0.2f * static_cast<float>(frames));  // breathing, 0..500 mL
    if (!frame(dv)) continue;
    ++frames;
    std::array<Box, 2> predicted;
    for (std::size_t v = 0; v < 2; ++v) {
      predicted[v] = projected_box(deformed_, *model_, located_[v], width(), height());
      const Box drawn = drawn_box(images_[v], width(), height());
      expect_box_near(drawn, predicted[v], kEdgeTolerancePx, v == 0 ? "left view" : "right view");
      // The rest shape would be drawn elsewhere: the deformation shows in the picture.
      const Box rest = projected_box(asset_.positions, *model_, located_[v], width(), height());
      largest_breath_shift = std::max(largest_breath_shift, rest.x0 - predicted[v].x0);
    }
    // Parallax: the left eye sees the lungs further right than the right eye does, by what the poses predict.
    const Box left = drawn_box(images_[0], width(), height());
    const Box right = drawn_box(images_[1], width(), height());
    const float predicted_parallax = predicted[0].cx() - predicted[1].cx();
    EXPECT_NEAR(left.cx() - right.cx(), predicted_parallax, 2.f);
    smallest_parallax = std::min(smallest_parallax, predicted_parallax);
    if (HasFailure()) break;
  }
  EXPECT_EQ(frames, 120);
  EXPECT_EQ(out.frames_submitted(), 120u);
  // The checks above had something to tell apart: breathing moves the silhouette by pixels, and the eyes (the
  // runtime's IPD apart) see the lungs pixels apart.
  EXPECT_GT(largest_breath_shift, 4.f);
  EXPECT_GT(smallest_parallax, 5.f);
  const glm::vec3 l(located_[0].pose.position.x, located_[0].pose.position.y, located_[0].pose.position.z);
  const glm::vec3 r(located_[1].pose.position.x, located_[1].pose.position.y, located_[1].pose.position.z);
  EXPECT_GT(glm::length(r - l), 0.05f) << "the views' poses are an IPD apart";
  std::printf("views %dx%d, %s; parallax >= %.1f px, breathing moved the silhouette up to %.1f px\n", width(),
              height(), out.formats().c_str(), smallest_parallax, largest_breath_shift);
}

TEST_F(OpenXrLungs, SimulatedHeadMotionMovesThePicture) {
  start(SimulatedHead::Moving);
  ASSERT_FALSE(HasFatalFailure());
  std::optional<Box> first;
  float largest_move = 0.f;
  // The simulated head wobbles over seconds: 3 s of frames at 20 Hz.
  for (int loop = 0, frames = 0; frames < 60 && loop < 300; ++loop) {
    if (!frame(250.f)) continue;
    ++frames;
    const Box drawn = drawn_box(images_[0], width(), height());
    expect_box_near(drawn, projected_box(deformed_, *model_, located_[0], width(), height()), kEdgeTolerancePx,
                    "left view");
    if (!first) first = drawn;
    largest_move = std::max(largest_move, std::hypot(drawn.cx() - first->cx(), drawn.cy() - first->cy()));
    if (HasFailure()) break;
  }
  // The lungs stand still and breathe at a constant volume: only the head moved the picture.
  EXPECT_GT(largest_move, 10.f);
  std::printf("the simulated head moved the picture by up to %.1f px\n", largest_move);
}

TEST_F(OpenXrLungs, FixedHeadGivesTheSamePictureEveryFrame) {
  start(SimulatedHead::Fixed);
  ASSERT_FALSE(HasFatalFailure());
  std::optional<std::array<std::vector<std::uint8_t>, 2>> first;
  int frames = 0;
  for (int loop = 0; frames < 20 && loop < 200; ++loop) {
    if (!frame(250.f)) continue;
    ++frames;
    if (!first) {
      first = images_;
      continue;
    }
    ASSERT_EQ(images_[0], (*first)[0]) << "frame " << frames;
    ASSERT_EQ(images_[1], (*first)[1]) << "frame " << frames;
  }
  EXPECT_EQ(frames, 20);
}

}  // namespace
}  // namespace lungar::test
