/// @file spaam_screen_test.cpp
/// @brief The SPAAM screen read back from a headless framebuffer: the crosshair's centre lands on the pixel asked
///        for (origin top-left of the eye's panel, scaled to its viewport), in the calibrated eye's viewport only,
///        with the prompt over it; the other eye's viewport stays black.
#include <gtest/gtest.h>

#include <GLES3/gl3.h>

#include <cstdint>
#include <vector>

#include "platform/registration/spaam_screen.h"
#include "render/frame_target.h"
#include "tests/render/gl_fixture.h"

namespace lungar::platform {
namespace {

class SpaamScreenTest : public test::GlTest {};

constexpr int kW = 640, kH = 240;        // the framebuffer: two eyes side by side
constexpr int kEyeW = 640, kEyeH = 480;  // each eye's panel: the viewports show it at half size
const std::array<render::Viewport, 2> kViewports{render::Viewport{0, 0, kW / 2, kH},
                                                 render::Viewport{kW / 2, 0, kW / 2, kH}};

/// Green at (column, row from the top).
bool lit(const std::vector<std::uint8_t>& rgba, int column, int row) {
  return rgba[static_cast<std::size_t>((row * kW + column) * 4 + 1)] > 200;
}

std::vector<std::uint8_t> drawn(int eye, const Eigen::Vector2d& pixel) {
  auto target = render::FrameTarget::create(kW, kH);
  EXPECT_TRUE(target) << target.error();
  target->bind();
  glClearColor(1.f, 1.f, 1.f, 1.f);  // white: what the screen does not clear shows
  glClear(GL_COLOR_BUFFER_BIT);
  SpaamScreen screen;
  screen.draw(kViewports, eye, kEyeW, kEyeH, pixel, {"RIGHT EYE 1/25", "", "", ""});
  std::vector<std::uint8_t> rgba;
  render::read_pixels_top_down(0, 0, kW, kH, rgba);
  return rgba;
}

TEST_F(SpaamScreenTest, TheCrosshairCentreIsLitAtTheAskedPixelOfTheRightEyeAndTheLeftIsDark) {
  const std::vector<std::uint8_t> rgba = drawn(1, {200.5, 300.5});
  const int column = kW / 2 + 100, row = 150;  // (200.5, 300.5) of a 640 x 480 panel in a 320 x 240 viewport
  EXPECT_TRUE(lit(rgba, column, row)) << "the centre";
  EXPECT_TRUE(lit(rgba, column + 25, row)) << "the right arm";
  EXPECT_TRUE(lit(rgba, column, row - 25)) << "the upper arm";
  EXPECT_FALSE(lit(rgba, column + 5, row + 5)) << "between the arms";
  EXPECT_FALSE(lit(rgba, column, row + 60)) << "past the arm's end";
  int left_bright = 0, right_text = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const std::uint8_t* p = &rgba[static_cast<std::size_t>((y * kW + x) * 4)];
      const bool any = p[0] > 30 || p[1] > 30 || p[2] > 30;
      if (x < kW / 2) {
        left_bright += any;
      } else if (y < 20 && lit(rgba, x, y)) {
        ++right_text;
      }
    }
  }
  EXPECT_EQ(left_bright, 0) << "the other eye's viewport is black";
  EXPECT_GT(right_text, 40) << "the prompt at the top of the right eye's viewport";
}

TEST_F(SpaamScreenTest, TheCrosshairStaysInsideItsViewportAtTheEdge) {
  const std::vector<std::uint8_t> rgba = drawn(0, {639.5, 0.5});  // the left panel's top-right pixel
  EXPECT_TRUE(lit(rgba, kW / 2 - 1, 0));
  for (int y = 0; y < kH; ++y)
    for (int x = kW / 2; x < kW; ++x) ASSERT_FALSE(lit(rgba, x, y)) << "right eye lit at " << x << ", " << y;
}

}  // namespace
}  // namespace lungar::platform
