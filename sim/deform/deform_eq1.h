/// @file deform_eq1.h
/// @brief CPU eq. (1): D = T F with the asset's explicit truncated transfer rows (the paper's baseline).
#pragma once

#include <span>
#include <vector>

#include <Eigen/Core>

#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

/// The applied force F_J = A_J p(J; g) * 1000 / V_lung(g), p = p0 + gamma g.(x_J - c): one mL of swept volume
/// per lung, so that D is in mm per mL, with each lung's centre and volumes now (`patient`). One value a vertex.
void applied_force(const BakedAsset& asset, const PatientState& patient, const Eigen::Vector3d& g_lung,
                   std::span<float> force_out);

/// Eq. (1): D_I = sum_J T(I,J) F(J) over the stored rows (Eigen sparse product). Needs has_transfer_rows().
void displacement_eq1(const BakedAsset& asset, std::span<const float> force, std::span<float> d_out);

/// Buffers for eq. (1) per frame, sized once for an asset: deform() allocates nothing.
class Eq1Deformer {
 public:
  explicit Eq1Deformer(const BakedAsset& asset);
  /// Displaced positions (3 floats a vertex) of the patient now, for gravity g (lung frame) and the pair's volume
  /// change.
  void deform(const PatientState& patient, const Eigen::Vector3d& g_lung, double delta_volume_ml,
              std::span<float> positions_out);
  std::span<const float> displacement() const { return d_; }

 private:
  const BakedAsset& asset_;
  std::vector<float> force_, d_;
};

}  // namespace lungar::sim
