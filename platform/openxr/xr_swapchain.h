/// @file xr_swapchain.h
/// @brief One OpenXR swapchain of GLES textures (a view's colour, or its depth for XR_KHR_composition_layer_depth):
/// creation, its images, acquire + wait + release; and the choice of formats among those the runtime offers.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "config/base/result.h"
#include "config/base/unique_handle.h"
#include "platform/openxr/xr_headers.h"

namespace lungar::platform::openxr {

/// sRGB first (GL_SRGB8_ALPHA8: the compositor reads the values as display values, as a monitor does), else
/// GL_RGBA8; nullopt when neither is offered.
std::optional<std::int64_t> choose_color_format(std::span<const std::int64_t> offered);
/// A depth format lungar's renderer can draw into: 32-bit float, then 24 with stencil, 24, then 16.
std::optional<std::int64_t> choose_depth_format(std::span<const std::int64_t> offered);
/// "GL_SRGB8_ALPHA8" and friends, for the log line that says which was chosen.
const char* gl_format_name(std::int64_t format);

class Swapchain {
 public:
  static Result<Swapchain> create(XrInstance instance, XrSession session, std::int64_t format, std::uint32_t width,
                                  std::uint32_t height, XrSwapchainUsageFlags usage, const char* what);
  /// xrAcquireSwapchainImage + xrWaitSwapchainImage: the GL texture to draw into this frame.
  Result<GLuint> acquire();
  /// xrReleaseSwapchainImage of the acquired image (no-op when none is acquired).
  Status release();

  XrSwapchain handle() const { return swapchain_.get(); }
  std::int64_t format() const { return format_; }
  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::size_t image_count() const { return images_.size(); }

 private:
  Swapchain() = default;
  XrInstance instance_ = XR_NULL_HANDLE;
  UniqueHandle<XrSwapchain, xrDestroySwapchain> swapchain_;
  std::int64_t format_ = 0;
  std::uint32_t width_ = 0, height_ = 0;
  std::vector<GLuint> images_;
  bool acquired_ = false;
  const char* what_ = "";
};

}  // namespace lungar::platform::openxr
