/// @file xr_view_math.h
/// @brief OpenXR poses and fields of view as lungar's eye views: metres to millimetres, XrPosef to a matrix, an
/// XrFovf's four angles to the off-axis projection OpenGL uses (the depth the composition layer describes).
///
/// OpenXR's spaces and lungar's head frame share the camera convention (+x right, +y up, looking down -z); lungar
/// works in millimetres, OpenXR in metres.
#pragma once

#include <glm/mat4x4.hpp>

#include "platform/openxr/xr_headers.h"
#include "render/stereo_view.h"

namespace lungar::platform::openxr {

inline constexpr float kMillimetresPerMetre = 1000.f;

/// The pose as a rigid transform (pose frame -> the space it is given in), translation in millimetres.
glm::mat4 pose_matrix_mm(const XrPosef& pose);

/// The OpenGL projection (clip z in [-w, w], window depth 0 at near, 1 at far) of an asymmetric field of view.
glm::mat4 projection_from_fov(const XrFovf& fov, float near_mm, float far_mm);

/// One view as an EyeView: `world_from_view` places the eye in lungar's world (mm); the viewport is the swapchain
/// image's rectangle.
render::EyeView eye_view(const glm::mat4& world_from_view, const XrFovf& fov, float near_mm, float far_mm,
                         const render::Viewport& viewport);

}  // namespace lungar::platform::openxr
