/// @file hmd_views.h
/// @brief The views of the outputs that lungar itself places on a screen (headless, X11 window, full-screen HMD
/// in extended mode): both eyes side by side in one target, each eye's view and off-axis projection from the
/// [hmd] settings (IPD, per-eye field of view), or one mono view.
/// @ingroup platform
#pragma once

#include <glm/mat4x4.hpp>

#include "platform/output/output_settings.h"
#include "platform/runtime/frame_output.h"
#include "render/stereo_view.h"

namespace lungar::platform {

/// The [hmd] settings as render/ takes them (render/ does not read config/); with a display calibration, each
/// eye's view and projection come from its 3 x 4 (calibrated_eye).
render::HmdGeometry hmd_geometry(const HmdSettings& hmd);
/// One eye's 3 x 4 (head sensor mm -> viewport pixels, origin top-left, row-major) as the view from the runtime's
/// head frame and an OpenGL projection with the config's near and far planes.
render::HmdGeometry::CalibratedEye calibrated_eye(const std::array<double, 12>& projection_3x4, const HmdSettings& hmd);

class HmdViews {
 public:
  HmdViews(const HmdSettings& hmd, int target_width_px, int target_height_px)
      : stereo_(hmd.view == View::Stereo), view_(hmd_geometry(hmd)), width_(target_width_px),
        height_(target_height_px) {}

  /// Stereo: left eye in the left half of the target, right eye in the right half; mono: the whole target.
  const FrameViews& views(const glm::mat4& head_to_world);
  /// The size a headless target needs: two eyes side by side, or one eye.
  static std::array<int, 2> target_size(const HmdSettings& hmd);

 private:
  bool stereo_;
  render::StereoView view_;
  int width_, height_;
  FrameViews views_;
};

}  // namespace lungar::platform
