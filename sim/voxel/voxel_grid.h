/// @file voxel_grid.h
/// @brief A 3-D grid of voxels placed in the lung frame (LPS, mm), and the binary mask of one lung on it.
///
/// Grid point (i, j, k) sits at origin + axes * (i, j, k): `axes` holds the voxel steps as columns, so a label
/// map's direction cosines and spacing (whatever its storage order: LPS, RAS, oblique) are carried exactly.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>  // determinant(), for voxel_volume_mm3()

#include <array>
#include <cstdint>
#include <vector>

namespace lungar::sim {

struct VoxelGrid {
  std::array<int, 3> size{0, 0, 0};
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();    ///< grid point (0, 0, 0), mm, LPS
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns: one step along i, j, k, mm, LPS

  std::int64_t count() const { return std::int64_t{size[0]} * size[1] * size[2]; }
  std::int64_t index(int i, int j, int k) const { return (std::int64_t{k} * size[1] + j) * size[0] + i; }
  Eigen::Vector3d point(const Eigen::Vector3d& ijk) const { return origin + axes * ijk; }
  double voxel_volume_mm3() const { return std::abs(axes.determinant()); }
};

/// Voxels inside one lung: 1 inside, 0 outside.
struct VoxelMask {
  VoxelGrid grid;
  std::vector<std::uint8_t> inside;
};

}  // namespace lungar::sim
