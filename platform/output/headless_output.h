/// @file headless_output.h
/// @brief Frames drawn off-screen (surfaceless EGL, Mesa llvmpipe where there is no GPU) into a framebuffer
/// object, finished with glFinish: the output of tests, the bench, CI and a machine without a display.
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
#include "render/frame_target.h"

namespace lungar::platform {

class HeadlessOutput final : public FrameOutput {
 public:
  /// A target two eyes (stereo) or one eye (mono) in size, on `context` (made current), or on a new surfaceless
  /// context when none is given. Several outputs may share one context (the bench measures one per configuration).
  /// `max_fps` (display.max_fps): at most this many frames a second; 0: unpaced.
  static Result<std::unique_ptr<HeadlessOutput>> create(const HmdSettings& hmd,
                                                        std::shared_ptr<EglContext> context = nullptr,
                                                        double max_fps = 0);

  std::string describe() const override;
  bool poll_events() override { return true; }
  Result<FrameTiming> begin_frame(std::int64_t now_ns) override {
    pacer_.wait(now_ns);
    return FrameTiming{};
  }
  const FrameViews& views(const glm::mat4& head_to_world) override { return views_.views(head_to_world); }
  void bind_target(std::size_t) override;
  Status finish_scene(const FrameViews& views) override;
  std::array<int, 2> target_size() const override { return {target_->width(), target_->height()}; }
  Status end_frame() override;
  Status snapshot(const std::string& png_path) override;

 private:
  HeadlessOutput(std::shared_ptr<EglContext> context, const HmdSettings& hmd, render::FrameTarget target,
                 double max_fps);
  std::shared_ptr<EglContext> context_;
  std::optional<render::FrameTarget> target_;
  std::optional<LensPass> lens_;  ///< with hmd.lens.enabled
  HmdViews views_;
  FramePacer pacer_;
};

}  // namespace lungar::platform
