/// @file breath_share.cpp
/// @brief The posture's split of the breath between the lungs (O(lungs): the runtime calls it every frame).
#include "sim/force/breath_share.h"

#include <algorithm>
#include <cmath>

#include "sim/force/force_sh.h"

namespace lungar::sim {

namespace {

Eigen::Vector3d centre_of(const LungState& lung) {
  return Eigen::Vector3d(lung.centre[0], lung.centre[1], lung.centre[2]);
}

/// The part of its healthy swept volume a lung whose response a pathology changed still sweeps with gravity g:
/// V(g) / V_healthy(g), V(g) = p0 v0 + gamma g.v (or ARDS's, force_sh.h); 1 when healthy.
double response_left(const BakedAsset& a, const LungState& lung, const Eigen::Vector3d& g) {
  if (!lung.healthy_volumes) return 1.0;
  const auto& h = *lung.healthy_volumes;
  const double healthy = a.p0 * h[0] + a.gamma_per_mm * (g.x() * h[1] + g.y() * h[2] + g.z() * h[3]);
  const double now = swept_volume_mm3(a, lung, g);
  return healthy > 0 ? std::max(0.0, now / healthy) : 1.0;
}

/// V_l w_l r_l(g) (1 + k g.u_l) for lung l (see the header), with `pair_centre` the volume-weighted centre.
double weight(const BakedAsset& a, const PatientState& patient, std::size_t l, const Eigen::Vector3d& pair_centre,
              const Eigen::Vector3d& g) {
  const LungState& lung = patient.lungs[l];
  const Eigen::Vector3d offset = centre_of(lung) - pair_centre;
  const double length = offset.norm();
  const double down = length > 1e-9 ? g.dot(offset) / length : 0.0;
  return a.lungs[l].volume_share * lung.breath_weight * response_left(a, lung, g) * (1.0 + kDependentLungGain * down);
}

}  // namespace

double breath_share(const BakedAsset& asset, const PatientState& patient, std::size_t lung,
                    const Eigen::Vector3d& g_lung) {
  const BakedLung& own = asset.lungs.at(lung);
  const double g_norm = g_lung.norm();
  if (asset.lungs.size() < 2) return own.volume_share;
  // No usable gravity: no posture term, the rest volumes (and any pathology's weights) alone.
  const bool has_g = std::isfinite(g_norm) && g_norm > 0;
  const Eigen::Vector3d g = has_g ? Eigen::Vector3d(g_lung / g_norm) : Eigen::Vector3d::Zero();
  Eigen::Vector3d pair_centre = Eigen::Vector3d::Zero();
  double volume = 0;
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) {
    pair_centre += asset.lungs[l].volume_share * centre_of(patient.lungs.at(l));
    volume += asset.lungs[l].volume_share;
  }
  if (!(volume > 0)) return own.volume_share;
  pair_centre /= volume;
  double total = 0;
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) total += weight(asset, patient, l, pair_centre, g);
  return total > 0 ? volume * weight(asset, patient, lung, pair_centre, g) / total : own.volume_share;
}

}  // namespace lungar::sim
