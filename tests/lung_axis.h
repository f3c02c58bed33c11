/// @file lung_axis.h
/// @brief Test helper: the vertical line through a lung's vertices' centroid and how far down and up it stays inside
///        that lung, to place a point (a lesion, a probe) a given fraction of the lung's height above its base.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>

#include "sim/asset/baked_asset.h"
#include "sim/motion/interior_displacement.h"

namespace lungar::testing {

struct LungAxis {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< of the lung's rest vertices
  double low_z = 1e9, high_z = -1e9;                   ///< low above high: the line meets no inside point
  /// The point `up` of the way from the lowest inside point to the highest (0: the base, 1: the apex).
  Eigen::Vector3d at(double up) const { return {centroid.x(), centroid.y(), low_z + up * (high_z - low_z)}; }
};

/// Lung `l`'s axis, its inside found in 0.5 mm steps over 400 mm either side of the centroid.
inline LungAxis lung_axis(const sim::BakedAsset& a, const sim::InteriorDisplacement& field, std::size_t l) {
  const sim::BakedLung& lung = a.lungs.at(l);
  LungAxis axis;
  for (std::uint32_t i = lung.first_vertex; i < lung.first_vertex + lung.vertex_count; ++i)
    axis.centroid += Eigen::Vector3d(a.positions[3 * i], a.positions[3 * i + 1], a.positions[3 * i + 2]);
  axis.centroid /= lung.vertex_count;
  const Eigen::Vector3d& c = axis.centroid;
  for (double z = c.z() - 400; z < c.z() + 400; z += 0.5)
    if (field.lung_containing({c.x(), c.y(), z}) == static_cast<int>(l)) {
      axis.low_z = std::min(axis.low_z, z);
      axis.high_z = std::max(axis.high_z, z);
    }
  return axis;
}

}  // namespace lungar::testing
