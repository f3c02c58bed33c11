/// @file xr_view_math_test.cpp
/// @brief OpenXR pose and field-of-view conversions: an asymmetric field of view projects a point at known tangents
/// to the image fraction the angles give, depth runs 0 at near to 1 at far, poses come out in millimetres.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "platform/openxr/xr_view_math.h"

namespace lungar::platform::openxr {
namespace {

// A headset's left eye: more field toward the temple (left) than the nose, more down than up.
const XrFovf kFov{-0.9f, 0.6f, 0.7f, -0.8f};  // angleLeft, angleRight, angleUp, angleDown (radians)

glm::vec3 ndc(const glm::mat4& projection, const glm::vec3& p) {
  const glm::vec4 c = projection * glm::vec4(p, 1.f);
  return glm::vec3(c) / c.w;
}

TEST(XrViewMath, AsymmetricFieldOfViewProjectsByTheTangentsOfItsAngles) {
  const glm::mat4 p = projection_from_fov(kFov, 100.f, 4000.f);
  // A point along each edge of the field lands on that edge of the image.
  const float z = -700.f;
  EXPECT_NEAR(ndc(p, {std::tan(kFov.angleLeft) * -z, 0.f, z}).x, -1.f, 1e-5f);
  EXPECT_NEAR(ndc(p, {std::tan(kFov.angleRight) * -z, 0.f, z}).x, 1.f, 1e-5f);
  EXPECT_NEAR(ndc(p, {0.f, std::tan(kFov.angleUp) * -z, z}).y, 1.f, 1e-5f);
  EXPECT_NEAR(ndc(p, {0.f, std::tan(kFov.angleDown) * -z, z}).y, -1.f, 1e-5f);
  // Straight ahead is off centre by the asymmetry: (0 - tan l) / (tan r - tan l) of the width from the left.
  const float fraction = -std::tan(kFov.angleLeft) / (std::tan(kFov.angleRight) - std::tan(kFov.angleLeft));
  EXPECT_NEAR(0.5f * (ndc(p, {0.f, 0.f, z}).x + 1.f), fraction, 1e-5f);
  // Window depth (glDepthRangef's 0..1): 0 at near, 1 at far, as the depth layer's nearZ and farZ say.
  EXPECT_NEAR(0.5f * (ndc(p, {0.f, 0.f, -100.f}).z + 1.f), 0.f, 1e-5f);
  EXPECT_NEAR(0.5f * (ndc(p, {0.f, 0.f, -4000.f}).z + 1.f), 1.f, 1e-4f);
}

TEST(XrViewMath, PoseIsARigidTransformInMillimetres) {
  XrPosef pose{};
  const glm::quat q = glm::angleAxis(glm::radians(30.f), glm::normalize(glm::vec3(0.2f, 1.f, 0.1f)));
  pose.orientation = {q.x, q.y, q.z, q.w};
  pose.position = {0.1f, 1.6f, -0.25f};
  const glm::mat4 m = pose_matrix_mm(pose);
  const glm::vec3 origin(m * glm::vec4(0.f, 0.f, 0.f, 1.f));
  EXPECT_NEAR(origin.x, 100.f, 1e-3f);
  EXPECT_NEAR(origin.y, 1600.f, 1e-3f);
  EXPECT_NEAR(origin.z, -250.f, 1e-3f);
  const glm::vec3 ahead = glm::vec3(m * glm::vec4(0.f, 0.f, -1.f, 0.f));
  const glm::vec3 expected = q * glm::vec3(0.f, 0.f, -1.f);
  EXPECT_NEAR(glm::length(ahead - expected), 0.f, 1e-5f);
}

TEST(XrViewMath, EyeViewLooksFromTheViewPose) {
  XrPosef pose{};
  pose.orientation.w = 1.f;
  pose.position = {0.032f, 0.f, 0.f};
  const render::EyeView eye = eye_view(pose_matrix_mm(pose), kFov, 100.f, 4000.f, {0, 0, 320, 240});
  // The eye's own position is its view frame's origin; the viewport is the image's.
  const glm::vec3 at_eye(eye.view * glm::vec4(32.f, 0.f, 0.f, 1.f));
  EXPECT_NEAR(glm::length(at_eye), 0.f, 1e-4f);
  EXPECT_EQ(eye.viewport.width, 320);
  EXPECT_EQ(eye.viewport.height, 240);
}

}  // namespace
}  // namespace lungar::platform::openxr
