/// @file xr_formats_test.cpp
/// @brief Swapchain format choice (sRGB first, a depth format the renderer draws into) and the GLES version check
/// against the runtime's requirements.
#include <gtest/gtest.h>

#include <vector>

#include "platform/openxr/xr_egl_binding.h"
#include "platform/openxr/xr_swapchain.h"

namespace lungar::platform::openxr {
namespace {

TEST(XrFormats, PrefersSrgbColourWhateverTheRuntimesOrder) {
  // Monado's order: RGBA16, RGBA16F, SRGB8_ALPHA8, RGBA8, then depth formats.
  const std::vector<std::int64_t> monado = {0x805B, 0x881A, GL_SRGB8_ALPHA8, GL_RGBA8, 0x8CAC, GL_DEPTH_COMPONENT16,
                                            GL_DEPTH24_STENCIL8, 0x8CAD};
  EXPECT_EQ(choose_color_format(monado), GL_SRGB8_ALPHA8);
  EXPECT_EQ(choose_depth_format(monado), 0x8CAC);  // GL_DEPTH_COMPONENT32F
  const std::vector<std::int64_t> linear_only = {GL_RGBA8, GL_DEPTH24_STENCIL8};
  EXPECT_EQ(choose_color_format(linear_only), GL_RGBA8);
  EXPECT_EQ(choose_depth_format(linear_only), GL_DEPTH24_STENCIL8);
  const std::vector<std::int64_t> none = {0x881A};
  EXPECT_FALSE(choose_color_format(none));
  EXPECT_FALSE(choose_depth_format(none));
  EXPECT_STREQ(gl_format_name(GL_SRGB8_ALPHA8), "GL_SRGB8_ALPHA8");
}

TEST(XrFormats, GlesVersionMustLieInTheRuntimesRange) {
  const XrVersion min = XR_MAKE_VERSION(3, 0, 0), max = XR_MAKE_VERSION(3, 2, 0);
  EXPECT_TRUE(gles_version_in_range(3, 0, min, max));
  EXPECT_TRUE(gles_version_in_range(3, 2, min, max));
  EXPECT_FALSE(gles_version_in_range(2, 0, min, max));
  EXPECT_FALSE(gles_version_in_range(3, 3, min, max));
  // Monado states [2.0, 3.2]: lungar's 3.x contexts fit.
  EXPECT_TRUE(gles_version_in_range(3, 1, XR_MAKE_VERSION(2, 0, 0), max));
}

}  // namespace
}  // namespace lungar::platform::openxr
