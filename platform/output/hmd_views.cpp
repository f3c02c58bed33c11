/// @file hmd_views.cpp
/// @brief Side-by-side eye views from the HMD geometry.
#include "platform/output/hmd_views.h"

namespace lungar::platform {

render::HmdGeometry hmd_geometry(const HmdSettings& s) {
  return {s.ipd_mm,       s.fov_inner_deg, s.fov_outer_deg,  s.fov_up_deg, s.fov_down_deg,
          s.eye_width_px, s.eye_height_px, s.near_mm,        s.far_mm};
}

std::array<int, 2> HmdViews::target_size(const HmdSettings& hmd) {
  const int eyes = hmd.view == View::Stereo ? 2 : 1;
  return {eyes * hmd.eye_width_px, hmd.eye_height_px};
}

const FrameViews& HmdViews::views(const glm::mat4& head_to_world) {
  views_.shared_target = true;
  if (stereo_) {
    views_.eyes = view_.eyes(head_to_world);
    views_.count = 2;
  } else {
    views_.eyes[0] = view_.mono(head_to_world, width_, height_);
    views_.count = 1;
  }
  // The eyes fill the target side by side whatever its size (a window may not be two eyes wide).
  const int n = static_cast<int>(views_.count);
  for (int e = 0; e < n; ++e) views_.eyes[e].viewport = {e * width_ / n, 0, width_ / n, height_};
  return views_;
}

}  // namespace lungar::platform
