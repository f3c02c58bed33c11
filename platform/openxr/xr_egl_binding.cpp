/// @file xr_egl_binding.cpp
/// @brief XR_MNDX_egl_enable's binding and the GLES requirements check.
#include "platform/openxr/xr_egl_binding.h"

#include "platform/openxr/xr_error.h"

namespace lungar::platform::openxr {

bool gles_version_in_range(int major, int minor, XrVersion min, XrVersion max) {
  const auto packed = [](long a, long b) { return a * 1000 + b; };
  const long have = packed(major, minor);
  return have >= packed(XR_VERSION_MAJOR(min), XR_VERSION_MINOR(min)) &&
         have <= packed(XR_VERSION_MAJOR(max), XR_VERSION_MINOR(max));
}

Result<XrGraphicsBindingEGLMNDX> egl_binding(const Instance& instance, const EglContext& context) {
  auto f = instance.function("xrGetOpenGLESGraphicsRequirementsKHR");
  if (!f) return fail(f.error());
  auto requirements_call = reinterpret_cast<PFN_xrGetOpenGLESGraphicsRequirementsKHR>(*f);
  auto requirements = xr_struct<XrGraphicsRequirementsOpenGLESKHR>(XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_ES_KHR);
  if (XrResult r = requirements_call(instance.handle(), instance.system(), &requirements); XR_FAILED(r)) {
    return fail(xr_error(instance.handle(), "xrGetOpenGLESGraphicsRequirementsKHR", r));
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (!gles_version_in_range(major, minor, requirements.minApiVersionSupported,
                             requirements.maxApiVersionSupported)) {
    const auto text = [](XrVersion v) {
      return std::to_string(XR_VERSION_MAJOR(v)) + "." + std::to_string(XR_VERSION_MINOR(v));
    };
    return fail("OpenXR: " + instance.runtime().text() + ": expected an OpenGL ES version in [" +
                text(requirements.minApiVersionSupported) + ", " + text(requirements.maxApiVersionSupported) +
                "], the EGL context has " + std::to_string(major) + "." + std::to_string(minor));
  }
  auto binding = xr_struct<XrGraphicsBindingEGLMNDX>(XR_TYPE_GRAPHICS_BINDING_EGL_MNDX);
  binding.getProcAddress = eglGetProcAddress;
  binding.display = static_cast<EGLDisplay>(context.egl_display());
  binding.config = static_cast<EGLConfig>(context.egl_config());
  binding.context = static_cast<EGLContext>(context.egl_context());
  return binding;
}

}  // namespace lungar::platform::openxr
