/// @file window_output.h
/// @brief Frames shown in an X11 window through an EGL window surface: a desktop window, or full-screen on an
/// HMD's output in extended mode (display.x11_output); paced by the swap interval.
/// @ingroup platform
#pragma once

#include <memory>
#include <optional>

#include "platform/output/output_settings.h"
#include "platform/egl/egl_context.h"
#include "platform/output/frame_pacer.h"
#include "platform/output/hmd_views.h"
#include "platform/output/lens_pass.h"
#include "platform/runtime/frame_output.h"

namespace lungar::platform {

class WindowOutput final : public FrameOutput {
 public:
  /// Opens the window (display.output window or fullscreen) and makes its context current.
  static Result<std::unique_ptr<WindowOutput>> create(const DisplaySettings& display,
                                                      const HmdSettings& hmd);

  std::string describe() const override;
  bool poll_events() override { return context_->process_events(); }
  std::string take_keys() override { return context_->take_keys(); }
  Result<FrameTiming> begin_frame(std::int64_t now_ns) override {
    pacer_.wait(now_ns);  // on top of the swap interval, when display.max_fps asks for less
    return FrameTiming{};
  }
  const FrameViews& views(const glm::mat4& head_to_world) override { return views_.views(head_to_world); }
  void bind_target(std::size_t) override;
  Status finish_scene(const FrameViews& views) override;
  std::array<int, 2> target_size() const override { return {context_->width(), context_->height()}; }
  Status end_frame() override { return context_->swap_buffers(); }
  Status snapshot(const std::string& png_path) override;

 private:
  WindowOutput(std::unique_ptr<EglContext> context, const HmdSettings& hmd, double max_fps)
      : context_(std::move(context)), views_(hmd, context_->width(), context_->height()), pacer_(max_fps) {}
  void bind_window();
  std::unique_ptr<EglContext> context_;
  std::optional<LensPass> lens_;  ///< with hmd.lens.enabled: the HMD's lenses, corrected here
  HmdViews views_;
  FramePacer pacer_;
};

}  // namespace lungar::platform
