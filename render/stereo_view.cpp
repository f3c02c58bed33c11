/// @file stereo_view.cpp
/// @brief Off-axis per-eye frusta from the HMD's field of view.
#include "render/stereo_view.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace lungar::render {
namespace {
double tan_deg(double deg) { return std::tan(deg * M_PI / 180.0); }
}  // namespace

glm::mat4 StereoView::projection(bool left) const {
  const double n = hmd_.near_mm;
  const double inner = n * tan_deg(hmd_.fov_inner_deg);
  const double outer = n * tan_deg(hmd_.fov_outer_deg);
  // The left eye's temple is on its left (-x); the right eye's on its right.
  const double l = left ? -outer : -inner;
  const double r = left ? inner : outer;
  return glm::frustum(static_cast<float>(l), static_cast<float>(r), static_cast<float>(-n * tan_deg(hmd_.fov_down_deg)),
                      static_cast<float>(n * tan_deg(hmd_.fov_up_deg)), static_cast<float>(n),
                      static_cast<float>(hmd_.far_mm));
}

std::array<EyeView, 2> StereoView::eyes(const glm::mat4& head_to_world) const {
  std::array<EyeView, 2> out;
  for (int e = 0; e < 2; ++e) {
    const bool left = e == 0;
    if (hmd_.calibrated) {
      out[e].view = (*hmd_.calibrated)[e].eye_from_head * glm::inverse(head_to_world);
      out[e].projection = (*hmd_.calibrated)[e].projection;
    } else {
      const float offset = static_cast<float>((left ? -0.5 : 0.5) * hmd_.ipd_mm);
      const glm::mat4 eye_to_world = head_to_world * glm::translate(glm::mat4(1.f), glm::vec3(offset, 0.f, 0.f));
      out[e].view = glm::inverse(eye_to_world);
      out[e].projection = projection(left);
    }
    out[e].viewport = {left ? 0 : hmd_.eye_width_px, 0, hmd_.eye_width_px, hmd_.eye_height_px};
  }
  return out;
}

EyeView StereoView::mono(const glm::mat4& head_to_world, int width_px, int height_px) const {
  const double n = hmd_.near_mm;
  const double up = n * tan_deg(hmd_.fov_up_deg), down = n * tan_deg(hmd_.fov_down_deg);
  const double half_w = 0.5 * (up + down) * width_px / height_px;
  EyeView v;
  v.view = glm::inverse(head_to_world);
  v.projection = glm::frustum(static_cast<float>(-half_w), static_cast<float>(half_w), static_cast<float>(-down),
                              static_cast<float>(up), static_cast<float>(n), static_cast<float>(hmd_.far_mm));
  v.viewport = {0, 0, width_px, height_px};
  return v;
}

glm::mat4 look_from(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
  return glm::inverse(glm::lookAt(eye, target, up));
}

}  // namespace lungar::render
