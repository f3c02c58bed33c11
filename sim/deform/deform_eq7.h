/// @file deform_eq7.h
/// @brief CPU eq. (7): the per-vertex SH dot product D_I = sum_lm f_lm T^I_lm (mm per mL), and the displaced
///        positions p'_I = p_I + dV * volume_share * D_I * n_I. The reference for the vertex shader.
#pragma once

#include <span>

#include <Eigen/Core>

#include "sim/asset/baked_asset.h"

namespace lungar::sim {

/// D for every vertex (vertex_count values) from the per-lung force SH (lungs x L^2, lung-major).
void displacement_eq7(const BakedAsset& asset, std::span<const float> force_sh, std::span<float> d_out);

/// Displaced positions (3 floats a vertex) for the pair's volume change `delta_volume_ml`; no allocation.
void deform_eq7(const BakedAsset& asset, std::span<const float> force_sh, double delta_volume_ml,
                std::span<float> positions_out);

/// Eq. (7) against the exact linear basis: D_I = p0 tau0_I + gamma g.tau_I, scaled to mm per mL per lung.
void displacement_linear(const BakedAsset& asset, const Eigen::Vector3d& g_lung, std::span<float> d_out);

}  // namespace lungar::sim
