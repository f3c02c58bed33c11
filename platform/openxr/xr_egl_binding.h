/// @file xr_egl_binding.h
/// @brief Hands lungar's EGL context (GLES 3) to the runtime through XR_MNDX_egl_enable, after asking the runtime
/// which GLES versions it takes (xrGetOpenGLESGraphicsRequirementsKHR, which a session needs called first).
#pragma once

#include "config/base/result.h"
#include "platform/egl/egl_context.h"
#include "platform/openxr/xr_headers.h"
#include "platform/openxr/xr_instance.h"

namespace lungar::platform::openxr {

/// The binding for XrSessionCreateInfo::next. Fails with one line when the context's GLES version is outside the
/// runtime's range. The context must be current (its version is read with glGetIntegerv).
Result<XrGraphicsBindingEGLMNDX> egl_binding(const Instance& instance, const EglContext& context);

/// Whether GLES major.minor lies in [min, max] as the runtime states them (only major and minor count).
bool gles_version_in_range(int major, int minor, XrVersion min, XrVersion max);

}  // namespace lungar::platform::openxr
