/// @file real_sh.h
/// @brief Real orthonormal spherical harmonics Y_lm on the unit sphere (eq. 2-4's basis), up to 8 bands.
#pragma once

#include <Eigen/Core>

namespace lungar::sim {

inline constexpr int kMaxBands = 8;

/// Index of Y_lm in a coefficient vector: l^2 + l + m (band l holds 2l+1 values).
constexpr int sh_index(int l, int m) { return l * l + l + m; }

/// Writes Y_lm(u), l < bands, into out[0 .. bands^2); u must be a unit vector, 1 <= bands <= kMaxBands.
/// Orthonormal: the integral over the sphere of Y_lm Y_l'm' is 1 when (l,m) = (l',m'), else 0.
void real_sh(int bands, const Eigen::Vector3d& u, double* out);

}  // namespace lungar::sim
