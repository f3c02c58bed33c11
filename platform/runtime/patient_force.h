/// @file patient_force.h
/// @brief Frame step 2: the patient tracker's pose and the registration -> the lung frame in the world ->
/// gravity in the lung frame -> force SH per lung. Shared by the Runtime and the hardware-in-the-loop tests.
/// @ingroup platform
#pragma once

#include <array>
#include <span>

#include <Eigen/Geometry>

#include "sim/asset/baked_asset.h"
#include "sim/force/force_sh.h"

namespace lungar::platform {

/// The lung frame in the world: model -> patient sensor (the registration), then patient sensor -> world.
inline Eigen::Isometry3d lung_to_world(const Eigen::Isometry3d& patient_to_world,
                                       const Eigen::Isometry3d& registration) {
  return patient_to_world * registration;
}

/// Model -> patient-sensor transform from a registration's translation (mm) and unit quaternion (w, x, y, z).
Eigen::Isometry3d registration_isometry(const std::array<double, 3>& translation_mm,
                                        const std::array<double, 4>& rotation_wxyz);

/// Force SH of every lung (lungs x L^2, lung-major) of the patient now for the lung frame's orientation in the
/// world; allocates nothing.
void patient_force_sh(const sim::BakedAsset& asset, const sim::PatientState& patient, sim::ForceMode mode,
                      const Eigen::Quaterniond& lung_in_world, std::span<float> force_out);

}  // namespace lungar::platform
