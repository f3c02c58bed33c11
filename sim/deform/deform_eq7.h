/// @file deform_eq7.h
/// @brief CPU eq. (7): the per-vertex SH dot product D_I = sum_lm f_lm T^I_lm (mm per mL), and the displaced
///        positions p'_I = p_I + dV * share * (D_I e_I + r_I . w) (e_I the direction of motion, r_I . w
///        the off-axis part of the sliding model for gravity g, share the lung's part of the breath in that
///        posture, sim/force/breath_share.h). The reference for the vertex shader.
#pragma once

#include <array>

#include <span>

#include <Eigen/Core>

#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

/// D for every vertex (vertex_count values) from the per-lung force SH (lungs x L^2, lung-major).
void displacement_eq7(const BakedAsset& asset, std::span<const float> force_sh, std::span<float> d_out);

/// Displaced positions (3 floats a vertex) of the patient now for the pair's volume change `delta_volume_ml` and
/// lung-frame gravity `g_lung` (which the split and the off-axis part read); no allocation.
void deform_eq7(const BakedAsset& asset, const PatientState& patient, std::span<const float> force_sh,
                const Eigen::Vector3d& g_lung, double delta_volume_ml, std::span<float> positions_out);

/// Adds vertex i's off-axis displacement for the linear weights w, times `scale`, to out[0..2] (nothing for an
/// asset without the off-axis part).
inline void add_off_axis(const BakedAsset& asset, std::size_t i, const std::array<float, 4>& w, float scale,
                         float* out) {
  if (!asset.has_off_axis()) return;
  const float* r = asset.off_axis.data() + 12 * i;
  for (int c = 0; c < 3; ++c)
    out[c] += scale * (r[4 * c] * w[0] + r[4 * c + 1] * w[1] + r[4 * c + 2] * w[2] + r[4 * c + 3] * w[3]);
}

/// Eq. (7) against the exact linear basis: D_I = p0 tau0_I + gamma g.tau_I, scaled to mm per mL per lung.
void displacement_linear(const BakedAsset& asset, const PatientState& patient, const Eigen::Vector3d& g_lung,
                         std::span<float> d_out);

}  // namespace lungar::sim
