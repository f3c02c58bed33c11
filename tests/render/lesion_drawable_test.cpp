/// @file lesion_drawable_test.cpp
/// @brief A lesion (render/lesion_drawable.h) shows through opaque lungs, in each eye where its centre projects, as
///        a ball of its projected size, and follows its centre when the interior field moves it.
#include <gtest/gtest.h>

#include <cmath>

#include "render/frame_target.h"
#include "render/lesion_drawable.h"
#include "render/png_snapshot.h"
#include "render/renderer.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::render {
namespace {

constexpr int kLesionEyeW = 320, kLesionEyeH = 360;

/// The lesion's pixels in one eye's half: their centroid (top-down pixels) and count.
struct Blob {
  double x = 0, y = 0;
  int pixels = 0;
};

/// Yellow: much green with the red, little blue; neither lung's colour nor black is.
bool lesion_coloured(const std::uint8_t* p) { return p[0] > 60 && p[1] > 0.6 * p[0] && p[2] < 0.4 * p[1]; }

Blob blob_in(const std::vector<std::uint8_t>& rgba, int width, const Viewport& vp) {
  Blob b;
  for (int y = 0; y < vp.height; ++y)
    for (int x = vp.x; x < vp.x + vp.width; ++x)
      if (lesion_coloured(&rgba[4 * (static_cast<std::size_t>(y) * width + x)])) {
        b.x += x, b.y += y, ++b.pixels;
      }
  if (b.pixels > 0) b.x /= b.pixels, b.y /= b.pixels;
  return b;
}

/// Where a lung-frame point lands in an eye's viewport, in top-down pixels.
glm::vec2 projected(const EyeView& eye, const glm::vec3& p) {
  const glm::vec4 clip = eye.projection * eye.view * glm::vec4(p, 1.f);
  const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
  return {eye.viewport.x + (ndc.x + 1) * 0.5f * eye.viewport.width - 0.5f,
          eye.viewport.height - (ndc.y + 1) * 0.5f * eye.viewport.height - 0.5f};
}

class LesionDrawableTest : public test::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    asset_ = test::ellipsoid_pair_mesh(48, 64, 4, 5);
    force_.assign(16, 0.f);
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(drawable_, LungDrawable::create(asset_)));
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(renderer_, Renderer::create(*drawable_)));
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(lesion_, LesionDrawable::create()));
    ASSERT_NO_FATAL_FAILURE(test::emplace_or_fail(target_, FrameTarget::create(2 * kLesionEyeW, kLesionEyeH)));
    eyes_ = test::stereo_eyes(kLesionEyeW, kLesionEyeH, {0.f, -350.f, 50.f});
    lungs_[0] = {force_, 0.f, {0.45f, 0.6f, 0.95f}};
    lungs_[1] = {force_, 0.f, {0.9f, 0.45f, 0.45f}};
    frame_.lungs = lungs_;
    frame_.eyes = eyes_;
    frame_.mode = DrawMode::Mesh;  // opaque: nothing inside shows unless drawn over
  }

  /// The lungs, then the lesion at `centre`, read back.
  std::vector<std::uint8_t> draw_with_lesion(const glm::vec3& centre, float radius) {
    target_->bind();
    Status s = renderer_->draw(*drawable_, frame_);
    EXPECT_TRUE(s) << s.error();
    const LesionFrame one{centre, radius};
    lesion_->draw(std::span<const LesionFrame>(&one, 1), frame_.model, eyes_);
    std::vector<std::uint8_t> rgba;
    read_pixels_top_down(0, 0, target_->width(), target_->height(), rgba);
    return rgba;
  }

  sim::BakedAsset asset_;
  std::vector<float> force_;
  std::optional<LungDrawable> drawable_;
  std::optional<Renderer> renderer_;
  std::optional<LesionDrawable> lesion_;
  std::optional<FrameTarget> target_;
  std::array<EyeView, 2> eyes_;
  LungFrame lungs_[2];
  FrameInputs frame_;
};

TEST_F(LesionDrawableTest, ShowsThroughOpaqueLungsWhereItsCentreProjectsInEachEye) {
  const auto& c = asset_.lungs[0].centre;
  const glm::vec3 centre(c[0], c[1], c[2]);  // inside the lung: the mesh hides it from every side
  const std::vector<std::uint8_t> rgba = draw_with_lesion(centre, 15.f);
  for (const EyeView& eye : eyes_) {
    const Blob b = blob_in(rgba, target_->width(), eye.viewport);
    const glm::vec2 want = projected(eye, centre);
    ASSERT_GT(b.pixels, 20) << "the lesion inside the mesh is not seen in the eye at x " << eye.viewport.x;
    EXPECT_NEAR(b.x, want.x, 1.0);
    EXPECT_NEAR(b.y, want.y, 1.0);
    // A ball of radius r at distance z covers about pi (r f / z)^2 pixels, f the focal length in pixels.
    const glm::vec2 edge = projected(eye, centre + glm::vec3(0.f, 0.f, 15.f));
    const double radius_px = std::abs(edge.y - want.y);
    EXPECT_NEAR(b.pixels, 3.14159 * radius_px * radius_px, 0.25 * 3.14159 * radius_px * radius_px);
  }
}

TEST_F(LesionDrawableTest, FollowsItsCentreUpTheScreenAsItMovesCranially) {
  const auto& c = asset_.lungs[1].centre;
  const glm::vec3 centre(c[0], c[1], c[2] - 10.f);
  const std::vector<std::uint8_t> before = draw_with_lesion(centre, 10.f);
  const std::vector<std::uint8_t> after = draw_with_lesion(centre + glm::vec3(0.f, 0.f, 20.f), 10.f);
  const EyeView& left = eyes_[0];
  const Blob a = blob_in(before, target_->width(), left.viewport), b = blob_in(after, target_->width(), left.viewport);
  ASSERT_GT(a.pixels, 10);
  ASSERT_GT(b.pixels, 10);
  const double want_px = projected(left, centre).y - projected(left, centre + glm::vec3(0.f, 0.f, 20.f)).y;
  EXPECT_GT(want_px, 10.0) << "the case moves it visibly";
  EXPECT_NEAR(a.y - b.y, want_px, 1.0);
  EXPECT_NEAR(a.x, b.x, 1.0);
}

}  // namespace
}  // namespace lungar::render
