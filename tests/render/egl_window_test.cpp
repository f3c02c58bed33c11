/// @file egl_window_test.cpp
/// @brief The X11 output: a window with an EGL surface at a configured position shows the lungs. Needs an X server
/// ($DISPLAY, e.g. `Xvfb :99 &` then DISPLAY=:99); skipped without one. The headless context is covered by every
/// GL test.
#include <gtest/gtest.h>

#include <cstdlib>

#include "platform/egl/egl_context.h"
#include "render/frame_target.h"
#include "render/renderer.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

namespace lungar::render {
namespace {

TEST(EglWindowTest, MissingDisplayIsAClearError) {
  platform::WindowOptions o;
  o.display_name = ":12345";  // no server there
  auto w = platform::EglContext::window(o);
  ASSERT_FALSE(w);
  EXPECT_NE(w.error().find(":12345"), std::string::npos) << w.error();
  o.width_px = 0;
  auto bad = platform::EglContext::window(o);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("size"), std::string::npos) << bad.error();
}

TEST(EglWindowTest, DrawsIntoAnX11Window) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') GTEST_SKIP() << "no $DISPLAY (run under Xvfb to cover the window path)";
  platform::WindowOptions o;
  o.x_px = 40;
  o.y_px = 30;
  o.width_px = 2 * 200;
  o.height_px = 220;
  o.vsync = false;
  auto w = platform::EglContext::window(o);
  ASSERT_TRUE(w) << w.error();
  EXPECT_TRUE((*w)->has_window());
  EXPECT_NE((*w)->describe().find("x11"), std::string::npos);
  {
    const auto asset = test::ellipsoid_pair(10000, 2, 3);
    auto drawable = LungDrawable::create(asset);
    ASSERT_TRUE(drawable);
    auto renderer = Renderer::create(*drawable);
    ASSERT_TRUE(renderer);
    HmdGeometry hmd;
    hmd.eye_width_px = 200;
    hmd.eye_height_px = 220;
    const auto eyes = StereoView(hmd).eyes(look_from({0.f, -450.f, 0.f}, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}));
    const std::vector<float> force(4, 0.f);
    const LungFrame lungs[2] = {{force, 0.f, {0.45f, 0.6f, 0.95f}}, {force, 0.f, {0.9f, 0.45f, 0.45f}}};
    FrameInputs f;
    f.lungs = lungs;
    f.eyes = eyes;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the window's back buffer
    ASSERT_TRUE(renderer->draw(*drawable, f));
    std::vector<std::uint8_t> rgba;
    read_pixels_top_down(0, 0, o.width_px, o.height_px, rgba);
    std::size_t lit = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) lit += rgba[i] + rgba[i + 1] + rgba[i + 2] > 0;
    EXPECT_GT(lit, 1000u);
    EXPECT_TRUE((*w)->swap_buffers());
    EXPECT_TRUE((*w)->process_events());
  }  // GL objects go before their context
}

}  // namespace
}  // namespace lungar::render
