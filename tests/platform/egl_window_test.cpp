/// @file egl_window_test.cpp
/// @brief The X11 output: a window with an EGL surface at a configured position shows the lungs. Needs an X server
/// ($DISPLAY, e.g. `Xvfb :99 &` then DISPLAY=:99); skipped without one. The headless context is covered by every
/// GL test.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "platform/egl/egl_context.h"
#include "platform/egl/x11_outputs.h"
#include "render/frame_target.h"
#include "render/renderer.h"
#include "tests/render/gl_fixture.h"
#include "tests/render/synthetic_lungs.h"

// Xlib last: it defines macros (Status, Bool) that would rename the project's types.
#include <X11/Xlib.h>
#include <X11/extensions/Xrandr.h>

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

/// The geometry the X server gives the top-level window titled `title`, as another client sees it.
bool find_window(Display* x, const char* title, XWindowAttributes& out) {
  Window root_return = 0, parent = 0, *children = nullptr;
  unsigned count = 0;
  if (!XQueryTree(x, DefaultRootWindow(x), &root_return, &parent, &children, &count)) return false;
  bool found = false;
  for (unsigned i = 0; i < count && !found; ++i) {
    char* name = nullptr;
    if (XFetchName(x, children[i], &name) && name != nullptr) {
      found = std::strcmp(name, title) == 0 && XGetWindowAttributes(x, children[i], &out);
      XFree(name);
    }
  }
  if (children != nullptr) XFree(children);
  return found;
}

// An HMD in extended mode is an X output beside the desktop: display.x11_output names it and the full-screen window
// covers exactly its area. Xvfb has one output ("screen"), so the test adds a RandR monitor where an HMD would be.
TEST(EglWindowTest, FullScreenCoversTheNamedOutput) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') GTEST_SKIP() << "no $DISPLAY (run under Xvfb to cover the window path)";
  Display* x = XOpenDisplay(nullptr);
  ASSERT_NE(x, nullptr);
  const Atom name = XInternAtom(x, "LUNGAR-TEST-HMD", False);
  XRRMonitorInfo hmd{};
  hmd.name = name;
  hmd.x = 96;
  hmd.y = 48;
  hmd.width = 320;
  hmd.height = 180;
  hmd.mwidth = 120;
  hmd.mheight = 68;
  XRRSetMonitor(x, DefaultRootWindow(x), &hmd);
  XSync(x, False);
  {
    auto areas = platform::x11_monitors(x);
    ASSERT_TRUE(areas) << areas.error();
    platform::WindowOptions o;
    o.fullscreen = true;
    o.output = "LUNGAR-TEST-HMD";
    o.vsync = false;
    o.title = "lungar output test";
    auto w = platform::EglContext::window(o);
    ASSERT_TRUE(w) << w.error();
    EXPECT_EQ((*w)->x(), 96);
    EXPECT_EQ((*w)->y(), 48);
    EXPECT_EQ((*w)->width(), 320);
    EXPECT_EQ((*w)->height(), 180);
    XWindowAttributes seen{};
    ASSERT_TRUE(find_window(x, o.title.c_str(), seen)) << "the window is not on the X server";
    EXPECT_EQ(seen.x, 96);
    EXPECT_EQ(seen.y, 48);
    EXPECT_EQ(seen.width, 320);
    EXPECT_EQ(seen.height, 180);

    // A name the server does not have: one error that names it and lists what there is.
    o.output = "HDMI-9";
    auto missing = platform::EglContext::window(o);
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().find("'HDMI-9'"), std::string::npos) << missing.error();
    EXPECT_NE(missing.error().find("LUNGAR-TEST-HMD"), std::string::npos) << missing.error();
  }
  XRRDeleteMonitor(x, DefaultRootWindow(x), name);
  XCloseDisplay(x);
}

}  // namespace
}  // namespace lungar::render
