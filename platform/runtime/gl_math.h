/// @file gl_math.h
/// @brief The GL boundary of the runtime's mathematics: poses are Eigen isometries until they become the
/// matrices and vectors GLM hands to the shaders, here and nowhere else.
/// @ingroup platform
#pragma once

#include <array>

#include <Eigen/Geometry>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "drivers/pose/pose_sample.h"

namespace lungar::platform {

/// A tracked pose as the rigid transform sensor -> world (mm).
inline Eigen::Isometry3d pose_isometry(const drivers::PoseSample& s) { return s.transform(); }

inline glm::mat4 to_glm(const Eigen::Matrix4d& m) {
  const Eigen::Matrix4f f = m.cast<float>();
  glm::mat4 out;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) out[c][r] = f(r, c);  // both column-major: column c, row r
  }
  return out;
}

inline glm::mat4 to_glm(const Eigen::Isometry3d& m) { return to_glm(m.matrix()); }

inline glm::vec3 to_glm(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

}  // namespace lungar::platform
