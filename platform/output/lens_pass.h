/// @file lens_pass.h
/// @brief The HMD lens pre-distortion as the last pass of an output that places the eyes itself (an HMD driven
/// as a display): the scene is drawn into a target of its own, then warped into the output's framebuffer
/// before the status line goes on top. OpenXR runtimes correct their own lenses and take none.
/// @ingroup platform
#pragma once

#include <array>

#include "config/base/result.h"
#include "platform/output/output_settings.h"
#include "platform/runtime/frame_output.h"
#include "render/frame_target.h"
#include "render/lens_distortion.h"

namespace lungar::platform {

class LensPass {
 public:
  /// A scene target `width` x `height` pixels (the output's target 0) and the pass, from [hmd] and [hmd.lens].
  static Result<LensPass> create(const HmdSettings& hmd, int width, int height);

  /// Binds the scene's own target: where the frame is drawn while the pass is on.
  void bind_scene() { scene_.bind(); }
  /// Draws the scene, distorted, into the framebuffer bound by the caller (the output's own).
  Status apply(const FrameViews& views) const;

 private:
  LensPass(render::FrameTarget scene, render::LensDistortion pass) : scene_(std::move(scene)), pass_(std::move(pass)) {}
  render::FrameTarget scene_;
  render::LensDistortion pass_;
  render::LensParams params_;
  std::array<std::array<float, 2>, 2> centres_{};
};

}  // namespace lungar::platform
