// The status line: glyphs rasterise as drawn, and the blit lands in the top-left corner of the viewport.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <vector>

#include "platform/egl/egl_context.h"
#include "render/frame_target.h"
#include "render/hud_line.h"

using namespace lungar;

TEST(HudLine, GlyphsRasteriseTheirPixels) {
  auto ctx = platform::EglContext::headless();
  ASSERT_TRUE(ctx) << ctx.error();
  render::HudLine hud;
  hud.set_text("8-");
  ASSERT_EQ(hud.width(), 2 * render::HudLine::kCellW);
  const int stride = render::HudLine::kMaxChars * render::HudLine::kCellW;
  int lit_first = 0, lit_second = 0;
  for (int y = 0; y < render::HudLine::kCellH; ++y) {
    for (int x = 0; x < hud.width(); ++x) {
      const bool lit = hud.pixels()[(y * stride + x) * 4 + 1] > 0;
      (x < render::HudLine::kCellW ? lit_first : lit_second) += lit;
    }
  }
  EXPECT_EQ(lit_first, 13);  // "8": rows 111 101 111 101 111
  EXPECT_EQ(lit_second, 3);  // "-": one row of three
  EXPECT_EQ(render::HudLine::glyph('a'), render::HudLine::glyph('A'));
  EXPECT_EQ(render::HudLine::glyph('~'), 0);
}

TEST(HudLine, DrawsInTheTopLeftCornerOfTheViewport) {
  auto ctx = platform::EglContext::headless();
  ASSERT_TRUE(ctx) << ctx.error();
  auto target = render::FrameTarget::create(200, 100);
  ASSERT_TRUE(target) << target.error();
  target->bind();
  glClearColor(0.f, 0.f, 0.f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  render::HudLine hud;
  hud.set_text("60 FPS");
  hud.draw({100, 0, 100, 100}, 2);  // the right half, as the right eye
  std::vector<std::uint8_t> rgba;
  render::read_pixels_top_down(0, 0, 200, 100, rgba);
  int left = 0, right_top = 0, right_bottom = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 200; ++x) {
      if (rgba[(y * 200 + x) * 4 + 1] < 200) continue;  // green text only
      if (x < 100) ++left;
      else if (y < 20) ++right_top;
      else ++right_bottom;
    }
  }
  EXPECT_EQ(left, 0);
  EXPECT_EQ(right_bottom, 0);
  EXPECT_GT(right_top, 40);
}
