/// @file xr_headers.h
/// @brief The one way platform/openxr/ includes OpenXR: EGL and GLES 3 first, then the loader's headers with the
/// EGL platform (XR_MNDX_egl_enable's binding) and the OpenGL ES graphics API (its swapchain images) turned on, and the
/// timespec clock (XR_KHR_convert_timespec_time).
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <time.h>

#ifndef XR_USE_PLATFORM_EGL
#define XR_USE_PLATFORM_EGL
#endif
#ifndef XR_USE_TIMESPEC
#define XR_USE_TIMESPEC
#endif
#ifndef XR_USE_GRAPHICS_API_OPENGL_ES
#define XR_USE_GRAPHICS_API_OPENGL_ES
#endif
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

namespace lungar::platform::openxr {

/// An OpenXR structure, zeroed, with its type set (`next` null): what every call's input and output needs.
template <class T>
T xr_struct(XrStructureType type) {
  T value{};
  value.type = type;
  return value;
}

}  // namespace lungar::platform::openxr
