/// @file window_output.cpp
/// @brief An X11 window's default framebuffer as the target.
#include "platform/output/window_output.h"

#include <GLES3/gl3.h>

#include "render/png_snapshot.h"

namespace lungar::platform {

Result<std::unique_ptr<WindowOutput>> WindowOutput::create(const DisplaySettings& d,
                                                           const HmdSettings& hmd) {
  const bool fullscreen = d.output == Output::Fullscreen;
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
  std::unique_ptr<WindowOutput> output(new WindowOutput(context.take(), hmd, d.max_fps));
  if (hmd.lens.enabled) {
    const auto [w, h] = output->target_size();
    auto lens = LensPass::create(hmd, w, h);
    if (!lens) return lens.with_context("");
    output->lens_.emplace(lens.take());
  }
  return output;
}

std::string WindowOutput::describe() const {
  return context_->describe() + " (window, " + std::to_string(context_->width()) + "x" +
         std::to_string(context_->height()) + ")";
}

void WindowOutput::bind_window() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, context_->width(), context_->height());
}

void WindowOutput::bind_target(std::size_t) {
  if (lens_) {
    lens_->bind_scene();
  } else {
    bind_window();
  }
}

Status WindowOutput::finish_scene(const FrameViews& views) {
  if (!lens_) return ok();
  bind_window();
  return lens_->apply(views);
}

Status WindowOutput::snapshot(const std::string& png_path) {
  bind_window();  // the back buffer, before the swap
  return render::snapshot_png(png_path, 0, 0, context_->width(), context_->height());
}

}  // namespace lungar::platform
