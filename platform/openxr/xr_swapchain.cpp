/// @file xr_swapchain.cpp
/// @brief Swapchain creation, image enumeration and the acquire/wait/release cycle.
#include "platform/openxr/xr_swapchain.h"

#include <algorithm>
#include <string>
#include <utility>

#include "platform/openxr/xr_error.h"

#ifndef GL_DEPTH_COMPONENT32F
#define GL_DEPTH_COMPONENT32F 0x8CAC
#endif

namespace lungar::platform::openxr {
namespace {

std::optional<std::int64_t> first_offered(std::span<const std::int64_t> offered,
                                          std::initializer_list<std::int64_t> preference) {
  for (std::int64_t f : preference) {
    if (std::find(offered.begin(), offered.end(), f) != offered.end()) return f;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::int64_t> choose_color_format(std::span<const std::int64_t> offered) {
  return first_offered(offered, {GL_SRGB8_ALPHA8, GL_RGBA8});
}

std::optional<std::int64_t> choose_depth_format(std::span<const std::int64_t> offered) {
  return first_offered(offered,
                       {GL_DEPTH_COMPONENT32F, GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT16});
}

const char* gl_format_name(std::int64_t format) {
  switch (format) {
    case GL_SRGB8_ALPHA8: return "GL_SRGB8_ALPHA8";
    case GL_RGBA8: return "GL_RGBA8";
    case GL_DEPTH_COMPONENT32F: return "GL_DEPTH_COMPONENT32F";
    case GL_DEPTH24_STENCIL8: return "GL_DEPTH24_STENCIL8";
    case GL_DEPTH_COMPONENT24: return "GL_DEPTH_COMPONENT24";
    case GL_DEPTH_COMPONENT16: return "GL_DEPTH_COMPONENT16";
    default: return "an unnamed GL format";
  }
}

Result<Swapchain> Swapchain::create(XrInstance instance, XrSession session, std::int64_t format, std::uint32_t width,
                                    std::uint32_t height, XrSwapchainUsageFlags usage, const char* what) {
  Swapchain s;
  s.instance_ = instance;
  s.format_ = format;
  s.width_ = width;
  s.height_ = height;
  s.what_ = what;
  auto info = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
  info.usageFlags = usage;
  info.format = format;
  info.sampleCount = 1;
  info.width = width;
  info.height = height;
  info.faceCount = 1;
  info.arraySize = 1;
  info.mipCount = 1;
  const std::string call = std::string("xrCreateSwapchain(") + what + ", " + gl_format_name(format) + ")";
  if (XrResult r = xrCreateSwapchain(session, &info, s.swapchain_.out()); XR_FAILED(r)) {
    return fail(xr_error(instance, call.c_str(), r));
  }
  std::uint32_t count = 0;
  XrResult r = xrEnumerateSwapchainImages(s.swapchain_.get(), 0, &count, nullptr);
  if (XR_FAILED(r)) return fail(xr_error(instance, "xrEnumerateSwapchainImages", r));
  std::vector<XrSwapchainImageOpenGLESKHR> images(count, xr_struct<XrSwapchainImageOpenGLESKHR>(XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_ES_KHR));
  r = xrEnumerateSwapchainImages(s.swapchain_.get(), count, &count,
                                 reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data()));
  if (XR_FAILED(r)) return fail(xr_error(instance, "xrEnumerateSwapchainImages(OpenGL ES)", r));
  for (const auto& image : images) s.images_.push_back(image.image);
  return s;
}

Result<GLuint> Swapchain::acquire() {
  std::uint32_t index = 0;
  auto acquire = xr_struct<XrSwapchainImageAcquireInfo>(XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO);
  if (XrResult r = xrAcquireSwapchainImage(swapchain_.get(), &acquire, &index); XR_FAILED(r)) {
    return fail(xr_error(instance_, "xrAcquireSwapchainImage", r));
  }
  acquired_ = true;
  auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
  wait.timeout = XR_INFINITE_DURATION;
  if (XrResult r = xrWaitSwapchainImage(swapchain_.get(), &wait); XR_FAILED(r)) {
    return fail(xr_error(instance_, "xrWaitSwapchainImage", r));
  }
  if (index >= images_.size()) {
    return fail(std::string("OpenXR: ") + what_ + " swapchain: expected an image index below " +
                std::to_string(images_.size()) + ", got " + std::to_string(index));
  }
  return images_[index];
}

Status Swapchain::release() {
  if (!acquired_ || !swapchain_) return ok();
  acquired_ = false;
  auto release = xr_struct<XrSwapchainImageReleaseInfo>(XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO);
  if (XrResult r = xrReleaseSwapchainImage(swapchain_.get(), &release); XR_FAILED(r)) {
    return fail(xr_error(instance_, "xrReleaseSwapchainImage", r));
  }
  return ok();
}

}  // namespace lungar::platform::openxr
