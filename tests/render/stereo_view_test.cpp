/// @file stereo_view_test.cpp
/// @brief Per-eye views and asymmetric projections; level-of-detail counts. Pure mathematics, no GL.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/level_of_detail.h"
#include "render/stereo_view.h"

namespace lungar::render {
namespace {

glm::vec3 ndc(const glm::mat4& proj, const glm::vec3& p) {
  const glm::vec4 c = proj * glm::vec4(p, 1.f);
  return glm::vec3(c) / c.w;
}

TEST(StereoViewTest, FieldOfViewEdgesMapToTheViewportEdges) {
  HmdGeometry hmd;
  hmd.fov_inner_deg = 35;
  hmd.fov_outer_deg = 55;
  hmd.fov_up_deg = 40;
  hmd.fov_down_deg = 50;
  StereoView view(hmd);
  const float d = 1000.f;
  auto t = [](double deg) { return static_cast<float>(std::tan(deg * M_PI / 180.0)); };
  // Left eye: temple (outer) on the left, nose (inner) on the right.
  const glm::mat4 left = view.projection(true);
  EXPECT_NEAR(ndc(left, {-d * t(55), 0.f, -d}).x, -1.f, 1e-4);
  EXPECT_NEAR(ndc(left, {d * t(35), 0.f, -d}).x, 1.f, 1e-4);
  EXPECT_NEAR(ndc(left, {0.f, d * t(40), -d}).y, 1.f, 1e-4);
  EXPECT_NEAR(ndc(left, {0.f, -d * t(50), -d}).y, -1.f, 1e-4);
  const glm::mat4 right = view.projection(false);
  EXPECT_NEAR(ndc(right, {d * t(55), 0.f, -d}).x, 1.f, 1e-4);
  EXPECT_NEAR(ndc(right, {-d * t(35), 0.f, -d}).x, -1.f, 1e-4);
}

TEST(StereoViewTest, EyesAreAnIpdApartAndSideBySide) {
  HmdGeometry hmd;
  hmd.ipd_mm = 64;
  StereoView view(hmd);
  const glm::mat4 head = look_from({10.f, 20.f, 30.f}, {10.f, 500.f, 30.f}, {0.f, 0.f, 1.f});
  const auto eyes = view.eyes(head);
  const glm::vec3 l = glm::inverse(eyes[0].view)[3], r = glm::inverse(eyes[1].view)[3];
  EXPECT_NEAR(glm::length(l - r), 64.f, 1e-3);
  EXPECT_NEAR(glm::length(0.5f * (l + r) - glm::vec3(10.f, 20.f, 30.f)), 0.f, 1e-3);
  // Looking along +y with +z up, the head's right (forward x up) is +x: the right eye is at larger x.
  EXPECT_GT(r.x, l.x);
  EXPECT_EQ(eyes[0].viewport.x, 0);
  EXPECT_EQ(eyes[1].viewport.x, hmd.eye_width_px);
  EXPECT_EQ(view.target_width(), 2 * hmd.eye_width_px);
}

TEST(LevelOfDetailTest, CountFollowsProjectedArea) {
  LungRange lung{0, 1000000, 0, 0, 50000.0, glm::vec3(0.f), 120.f};
  const glm::mat4 near_mv = glm::translate(glm::mat4(1.f), glm::vec3(0.f, 0.f, -600.f));
  const glm::mat4 far_mv = glm::translate(glm::mat4(1.f), glm::vec3(0.f, 0.f, -1200.f));
  const auto n_near = lod_point_count(lung, near_mv, 1.f, 720, 5.f, 4.f);
  const auto n_far = lod_point_count(lung, far_mv, 1.f, 720, 5.f, 4.f);
  // Twice the distance from the front: about a quarter of the points.
  EXPECT_GT(n_near, 3 * n_far);
  EXPECT_LT(n_near, 6 * n_far);
  // Bigger points need fewer of them; a close lung is capped at its size.
  EXPECT_LT(lod_point_count(lung, near_mv, 1.f, 720, 10.f, 4.f), n_near);
  lung.vertex_count = 500;
  EXPECT_EQ(lod_point_count(lung, near_mv, 1.f, 720, 5.f, 4.f), 500u);
  EXPECT_EQ(lod_point_count(lung, glm::mat4(1.f), 1.f, 720, 5.f, 4.f), 500u);  // eye inside
}

}  // namespace
}  // namespace lungar::render
