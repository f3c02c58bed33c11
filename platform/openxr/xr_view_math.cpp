/// @file xr_view_math.cpp
/// @brief Pose and field-of-view conversions.
#include "platform/openxr/xr_view_math.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace lungar::platform::openxr {

glm::mat4 pose_matrix_mm(const XrPosef& pose) {
  const glm::quat q(pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z);
  glm::mat4 m = glm::mat4_cast(glm::normalize(q));
  m[3] = glm::vec4(pose.position.x * kMillimetresPerMetre, pose.position.y * kMillimetresPerMetre,
                   pose.position.z * kMillimetresPerMetre, 1.f);
  return m;
}

glm::mat4 projection_from_fov(const XrFovf& fov, float near_mm, float far_mm) {
  // angleLeft and angleDown are negative for a view centred on its axis.
  return glm::frustum(std::tan(fov.angleLeft) * near_mm, std::tan(fov.angleRight) * near_mm,
                      std::tan(fov.angleDown) * near_mm, std::tan(fov.angleUp) * near_mm, near_mm, far_mm);
}

render::EyeView eye_view(const glm::mat4& world_from_view, const XrFovf& fov, float near_mm, float far_mm,
                         const render::Viewport& viewport) {
  render::EyeView eye;
  eye.view = glm::inverse(world_from_view);
  eye.projection = projection_from_fov(fov, near_mm, far_mm);
  eye.viewport = viewport;
  return eye;
}

}  // namespace lungar::platform::openxr
