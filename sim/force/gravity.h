/// @file gravity.h
/// @brief Patient orientation -> unit gravity direction g in the lung frame (gravity is world -z).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lungar::sim {

/// g in the lung frame for the lung frame's orientation `lung_in_world` (world = q * lung):
/// g = R(q)^T (0, 0, -1). Upright (identity) gives (0, 0, -1), inferior; supine gives +y, posterior.
/// q need not be normalised; a zero or non-finite q counts as upright.
Eigen::Vector3d gravity_in_lung_frame(const Eigen::Quaterniond& lung_in_world);

/// Rotation by `angle` radians about lung-frame axis 0 = X, 1 = Y, 2 = Z.
Eigen::Quaterniond axis_rotation(int axis, double angle);

}  // namespace lungar::sim
