/// @file lens_distortion_test.cpp
/// @brief The lens pass: identity at k = 0, barrel pre-distortion shrinks the picture, per-channel k fringes colour.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include "render/lens_distortion.h"
#include "render/renderer.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::render {
namespace {

class LensDistortionTest : public test::GlTest {};

// Lit pixels of one channel.
std::size_t lit(const std::vector<std::uint8_t>& rgba, int channel) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) n += rgba[i + channel] > 8;
  return n;
}

TEST_F(LensDistortionTest, IdentityShrinkAndColourFringes) {
  const auto asset = test::ellipsoid_pair(20000, 2, 3);
  auto drawable = LungDrawable::create(asset);
  ASSERT_TRUE(drawable);
  auto renderer = Renderer::create(*drawable);
  ASSERT_TRUE(renderer);
  auto lens = LensDistortion::create();
  ASSERT_TRUE(lens) << lens.error();
  HmdGeometry hmd;
  hmd.eye_width_px = 256;
  hmd.eye_height_px = 288;
  const StereoView stereo(hmd);
  const auto eyes = stereo.eyes(look_from({0.f, -450.f, 0.f}, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}));
  auto scene = FrameTarget::create(stereo.target_width(), stereo.target_height());
  auto out = FrameTarget::create(stereo.target_width(), stereo.target_height());
  ASSERT_TRUE(scene && out);
  const std::vector<float> force(4, 0.f);
  const LungFrame lungs[2] = {{force, 0.f, {1.f, 1.f, 1.f}}, {force, 0.f, {1.f, 1.f, 1.f}}};  // white: all channels
  FrameInputs f;
  f.lungs = lungs;
  f.eyes = eyes;
  f.ambient = 1.f;
  scene->bind();
  ASSERT_TRUE(renderer->draw(*drawable, f));
  std::vector<std::uint8_t> undistorted, distorted;
  read_pixels_top_down(0, 0, scene->width(), scene->height(), undistorted);

  const std::array<std::array<float, 2>, 2> centres = {lens_centre(hmd, true), lens_centre(hmd, false)};
  auto pass = [&](const LensParams& p) {
    out->bind();
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT_TRUE(lens->apply(*scene, eyes, centres, p));
    read_pixels_top_down(0, 0, out->width(), out->height(), distorted);
    return distorted;
  };
  LensParams none;
  none.k1 = {0.f, 0.f, 0.f};
  none.k2 = {0.f, 0.f, 0.f};
  const auto same = pass(none);
  EXPECT_NEAR(static_cast<double>(lit(same, 1)), static_cast<double>(lit(undistorted, 1)), 0.01 * lit(undistorted, 1));

  // Strong enough to matter near the centre where the lungs are (r ~ 0.3): red bent least, blue most.
  LensParams barrel;
  barrel.k1 = {0.5f, 1.0f, 1.5f};
  barrel.k2 = {0.f, 0.f, 0.f};
  const auto bent = pass(barrel);
  EXPECT_LT(lit(bent, 1), lit(undistorted, 1) * 9 / 10);
  EXPECT_GT(lit(bent, 0), lit(bent, 1));  // chromatic: the blue image is the smallest
  EXPECT_GT(lit(bent, 1), lit(bent, 2));
  EXPECT_FALSE(lens->apply(*scene, eyes, std::span<const std::array<float, 2>>(centres.data(), 1), barrel));
}

}  // namespace
}  // namespace lungar::render
