/// @file breath_share.cpp
/// @brief The posture's split of the breath between the lungs (O(lungs): the runtime calls it every frame).
#include "sim/force/breath_share.h"

#include <cmath>

namespace lungar::sim {

namespace {

Eigen::Vector3d centre_of(const BakedLung& lung) {
  return Eigen::Vector3d(lung.centre[0], lung.centre[1], lung.centre[2]);
}

/// V_l (1 + k g.u_l) for every lung l (see the header), with `pair_centre` the volume-weighted centre.
double weight(const BakedLung& lung, const Eigen::Vector3d& pair_centre, const Eigen::Vector3d& g) {
  const Eigen::Vector3d offset = centre_of(lung) - pair_centre;
  const double length = offset.norm();
  const double down = length > 1e-9 ? g.dot(offset) / length : 0.0;
  return lung.volume_share * (1.0 + kDependentLungGain * down);
}

}  // namespace

double breath_share(const BakedAsset& asset, std::size_t lung, const Eigen::Vector3d& g_lung) {
  const BakedLung& own = asset.lungs.at(lung);
  const double g_norm = g_lung.norm();
  if (asset.lungs.size() < 2 || !std::isfinite(g_norm) || !(g_norm > 0)) return own.volume_share;
  const Eigen::Vector3d g = g_lung / g_norm;
  Eigen::Vector3d pair_centre = Eigen::Vector3d::Zero();
  double volume = 0;
  for (const BakedLung& l : asset.lungs) {
    pair_centre += l.volume_share * centre_of(l);
    volume += l.volume_share;
  }
  if (!(volume > 0)) return own.volume_share;
  pair_centre /= volume;
  double total = 0;
  for (const BakedLung& l : asset.lungs) total += weight(l, pair_centre, g);
  return total > 0 ? volume * weight(own, pair_centre, g) / total : own.volume_share;
}

}  // namespace lungar::sim
