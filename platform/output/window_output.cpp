/// @file window_output.cpp
/// @brief An X11 window's default framebuffer as the target.
#include "platform/output/window_output.h"

#include <GLES3/gl3.h>

#include "render/png_snapshot.h"

namespace lungar::platform {

Result<std::unique_ptr<WindowOutput>> WindowOutput::create(const config::DisplaySettings& d,
                                                           const config::HmdSettings& hmd) {
  const bool fullscreen = d.output == config::Output::Fullscreen;
  const auto [eyes_width, eyes_height] = HmdViews::target_size(hmd);
  WindowOptions w;
  w.x_px = d.x_px;
  w.y_px = d.y_px;
  w.width_px = fullscreen ? d.width_px : eyes_width;
  w.height_px = fullscreen ? d.height_px : eyes_height;
  w.fullscreen = fullscreen;
  w.output = d.x11_output;
  w.vsync = d.vsync;
  auto context = EglContext::window(w);
  if (!context) {
    // The field to fix: a named output that is not there, or no window at all.
    return context.with_context(fullscreen && !w.output.empty() ? "display.x11_output: " : "display: ");
  }
  return std::unique_ptr<WindowOutput>(new WindowOutput(context.take(), hmd, d.max_fps));
}

std::string WindowOutput::describe() const {
  return context_->describe() + " (window, " + std::to_string(context_->width()) + "x" +
         std::to_string(context_->height()) + ")";
}

void WindowOutput::bind_target(std::size_t) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, context_->width(), context_->height());
}

Status WindowOutput::snapshot(const std::string& png_path) {
  bind_target(0);  // the back buffer, before the swap
  return render::snapshot_png(png_path, 0, 0, context_->width(), context_->height());
}

}  // namespace lungar::platform
