/// @file synthetic_lungs.h
/// @brief In-memory baked assets for render tests and benchmarks: a pair of ellipsoidal "lungs" whose points are in
/// level-of-detail order (every prefix an even subsample, from the R2 low-discrepancy sequence), with coefficient
/// fields chosen by the test.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/asset/baked_asset.h"

namespace lungar::test {

/// Two ellipsoids (semi-axes 60 x 80 x 120 mm, LPS), the right lung at x = -90 mm and the left at +90 mm, with
/// `points_per_lung` points each and random T^I_lm in [-scale, scale] for `bands` bands; linear_coeffs random too.
sim::BakedAsset ellipsoid_pair(std::uint32_t points_per_lung, std::uint32_t bands, std::uint32_t seed,
                               float scale = 0.05f);

/// The same points as a lat-long mesh with triangles (not in LOD order), `rings` x `segments` per lung.
sim::BakedAsset ellipsoid_pair_mesh(std::uint32_t rings, std::uint32_t segments, std::uint32_t bands,
                                    std::uint32_t seed);

/// Replaces the coefficients of a bands = 2 asset by a local ("diagonal") transfer: T^I_lm = w A_I Y_lm(u_I), so that
/// D_I = w A_I sum_lm f_lm Y_lm(u_I) follows the force pattern at the vertex.
void set_local_transfer(sim::BakedAsset& asset, float w);

/// CPU eq. (7) in double: p'_I = p_I + dV sum_lm T^I_lm f_lm n_I, with one force per lung.
std::vector<double> deform_eq7(const sim::BakedAsset& asset, const std::vector<std::vector<float>>& force,
                               const std::vector<float>& volume_change_ml, bool linear_basis = false);

}  // namespace lungar::test
