/// @file lesion_rows.h
/// @brief A lesion's own coefficient rows: its displacement evaluated the paper's way, as a surface vertex's is, so
///        that the runtime moves it each frame with a dot product and no solve.
///
/// The interior field is linear in the surface's displacement (interior_displacement.h): the lesion's centre moves
/// by sum_I E_I u_I, E its weights on the surface vertices (InteriorDisplacement::surface_weights) and u_I a
/// vertex's displacement per mL, u_I = (T^I . f) e_I + R_I w (deform_eq7.h). Summed once at load, that is
///     u_lesion = A f + B w,   A = sum_I E_I e_I (T^I)'  (3 x L^2),   B = sum_I E_I R_I  (3 x 4),
/// and the lesion moves by dV times it, dV its lung's volume change: exactly what the surface's harmonic extension
/// gives at its centre for the same force, orientation and breath, for the cost of 3 (L^2 + 4) multiply-adds.
#pragma once

#include <Eigen/Core>

#include <array>
#include <span>
#include <vector>

#include "sim/asset/baked_asset.h"
#include "sim/motion/interior_displacement.h"
#include "sim/motion/lesion.h"

namespace lungar::sim {

struct LesionRows {
  PlacedLesion placed;
  std::vector<float> sh;             ///< A: rows x, y, z of L^2 values each, mm per mL per unit force SH
  std::array<float, 12> off_axis{};  ///< B: rows x, y, z of (r0, r_x, r_y, r_z), mm per mL per unit weight

  /// The lesion's displacement (mm, lung frame) for its lung's force SH f (L^2 values), linear weights w and
  /// volume change dV (mL), as the vertex shader moves a surface vertex. Allocates nothing.
  Eigen::Vector3d displacement(std::span<const float> force, const std::array<float, 4>& w, double dv_ml) const;
};

/// The rows of each placed lesion of `asset` (the asset `field` was built from).
std::vector<LesionRows> lesion_rows(const BakedAsset& asset, const InteriorDisplacement& field,
                                    const std::vector<PlacedLesion>& lesions);

}  // namespace lungar::sim
