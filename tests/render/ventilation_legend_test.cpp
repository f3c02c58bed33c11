// The ventilation map's legend: the ramp runs from the map's zero colour on the left to its full-scale colour on the
// right, in the bottom-left corner of the viewport, with its label above it.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "platform/egl/egl_context.h"
#include "render/frame_target.h"
#include "render/ventilation_legend.h"
#include "render/ventilation_ramp.h"

using namespace lungar;

TEST(VentilationLegend, TheBarRunsTheRampFromZeroToFullScaleInTheBottomLeftCorner) {
  auto ctx = platform::EglContext::headless();
  ASSERT_TRUE(ctx) << ctx.error();
  constexpr int kW = 800, kH = 200;
  auto target = render::FrameTarget::create(kW, kH);
  ASSERT_TRUE(target) << target.error();
  target->bind();
  glClearColor(0.f, 0.f, 0.f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT);
  render::VentilationLegend legend(12.f);
  legend.draw({400, 0, 400, 200}, 2);  // the right half, as the right eye
  std::vector<std::uint8_t> rgba;
  render::read_pixels_top_down(0, 0, kW, kH, rgba);
  auto pixel = [&](int x, int y_from_bottom) { return &rgba[static_cast<std::size_t>(((kH - 1 - y_from_bottom) * kW + x) * 4)]; };
  // The bar: 8 px in from the viewport's left and bottom, two font pixels a texel wide.
  const int y = 8 + 2, first = 400 + 8, last = 400 + 8 + render::VentilationLegend::kRampTexels * 4 - 1;
  const auto zero = render::ventilation_colour(0.f), full = render::ventilation_colour(1.f);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(pixel(first, y)[k], 255.f * zero[k], 1.5f) << k;
    EXPECT_NEAR(pixel(last, y)[k], 255.f * full[k], 1.5f) << k;
  }
  // Lighter all the way along (so it reads in grey): the sum of the channels grows.
  int previous = -1;
  for (int x = first; x <= last; x += 8) {
    const int sum = pixel(x, y)[0] + pixel(x, y)[1] + pixel(x, y)[2];
    EXPECT_GE(sum, previous) << "x " << x;
    previous = sum;
  }
  int left_half = 0, label = 0;
  for (int yy = 0; yy < kH; ++yy)
    for (int x = 0; x < kW; ++x) {
      const std::uint8_t* p = &rgba[static_cast<std::size_t>((yy * kW + x) * 4)];
      if (p[0] + p[1] + p[2] == 0) continue;
      if (x < 400) ++left_half;
      if (yy < kH - 8 - 12 && yy > kH - 60 && p[1] > 200 && p[0] < 150) ++label;  // green text above the bar
    }
  EXPECT_EQ(left_half, 0) << "drawn in its own viewport only";
  EXPECT_GT(label, 40) << "the label above the bar";
}

TEST(VentilationRamp, TheShadersStopsAreTheLegends) {
  // deform.vert's ventilation_ramp holds the same stops: checked through the shader in renderer_test; here the
  // ramp's own ends and its middle stop.
  EXPECT_FLOAT_EQ(render::ventilation_colour(-1.f)[1], 0.f);
  EXPECT_FLOAT_EQ(render::ventilation_colour(0.5f)[1], render::kVentilationStops[2][1]);
  EXPECT_FLOAT_EQ(render::ventilation_colour(2.f)[0], render::kVentilationStops[4][0]);
}
