/// @file ventral_share.h
/// @brief The part of a breath the anterior half of the lungs sweeps, in a posture, from the force SH alone: what
///        electrical impedance tomography reports as the ventral share (supine about 0.38 in awake adults, prone
///        about 0.49), and what `scripts/ply-shares` measures on an export.
///
/// The anterior half: the vertices whose rest depth (y, LPS: anterior is -y) lies in front of the middle of the
/// pair's extent in y. A vertex's first-order swept volume is A_I n_I . d_I, with d_I = s_l dV (D_I e_I + r_I w_l),
/// D_I = sum_lm T^I_lm f_lm (sim/motion/motion_figures.h): linear in f and w, so each lung's sums over its
/// anterior and its whole surface are folded once into L^2 + 4 numbers and a frame pays O(lungs x L^2).
#pragma once

#include <array>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

class VentralShare {
 public:
  /// Folds `asset`'s per-vertex rows (O(vertices x L^2), once).
  explicit VentralShare(const BakedAsset& asset);

  /// The anterior half's share of the pair's swept volume for the force SH `force` (lungs x L^2, lung-major, per
  /// mL as the runtime's) with gravity `g_lung` (lung frame): each lung weighted by its share of the breath in
  /// the posture (breath_share.h), the patient as `patient` is. 0 when the pair sweeps nothing.
  double share(const BakedAsset& asset, const PatientState& patient, std::span<const float> force,
               const Eigen::Vector3d& g_lung) const;

 private:
  struct Sums {
    std::vector<double> sh;          ///< sum of A_I (e_I . n_I) T^I_lm, L^2 values
    std::array<double, 4> off_axis{};  ///< sum of A_I n_I^T R_I (R_I the 3 x 4 off-axis rows)
  };
  std::vector<Sums> anterior_, whole_;  ///< per lung
};

}  // namespace lungar::sim
