/// @file patient_force.cpp
/// @brief Patient pose -> force SH (DESIGN.md, frame step 2).
#include "platform/runtime/patient_force.h"

namespace lungar::platform {

Eigen::Quaterniond lung_in_world(const Eigen::Quaterniond& patient_to_world, const Eigen::Quaterniond& registration) {
  return (patient_to_world * registration).normalized();
}

Eigen::Quaterniond registration_rotation(const config::RegistrationSettings& r) {
  const auto& q = r.rotation_wxyz;
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
}

void patient_force_sh(const sim::BakedAsset& asset, config::OrientationMode mode,
                      const Eigen::Quaterniond& lung_to_world, std::span<float> force_out) {
  const sim::ForceMode m =
      mode == config::OrientationMode::Exact ? sim::ForceMode::exact : sim::ForceMode::paper;
  sim::force_sh(asset, m, lung_to_world, force_out.data());
}

}  // namespace lungar::platform
