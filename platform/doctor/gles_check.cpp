/// @file gles_check.cpp
/// @brief The graphics check: a headless EGL context, its EGL and OpenGL ES versions and the renderer.
#include <cstdio>
#include <string>

#include "platform/doctor/checks.h"
#include "platform/egl/egl_context.h"

namespace lungar::platform::doctor {

namespace {

/// Mesa's and Google's CPU rasterisers: everything runs, but on the CPU cores the tracker and the frame loop share.
const char* software_renderer(const std::string& renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "SwiftShader", "lavapipe"}) {
    if (renderer.find(name) != std::string::npos) return name;
  }
  return nullptr;
}

}  // namespace

Check check_gles() {
  auto context = EglContext::headless();
  if (!context) {
    return failed("gles", context.error(),
                  "install Mesa's EGL and GLES drivers (sudo apt install libegl-mesa0 libgles2 libgl1-mesa-dri) or the "
                  "GPU vendor's EGL driver");
  }
  const EglContext::Versions v = (*context)->versions();
  const std::string& renderer = v.renderer;
  int major = 0, minor = 0;
  std::sscanf(v.gl.c_str(), "OpenGL ES %d.%d", &major, &minor);
  const std::string detail = "EGL " + v.egl + ", " + v.gl + ", renderer " + renderer;
  if (major < 3) {
    return failed("gles", detail + ": expected OpenGL ES 3.0 or later",
                  "use a GPU and driver with OpenGL ES 3.0 (Mesa 10.x or later; sudo apt install libgl1-mesa-dri)");
  }
  if (const char* soft = software_renderer(renderer)) {
    return warned("gles", detail + ": software rendering (" + soft + "), the CPU draws every frame",
                  "for a GPU: check that `ls -l /dev/dri` lists it and that this user may open it (group render or "
                  "video), and that its Mesa or vendor EGL driver is installed");
  }
  return passed("gles", detail + ": hardware rendering");
}

}  // namespace lungar::platform::doctor
