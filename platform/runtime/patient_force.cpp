/// @file patient_force.cpp
/// @brief Patient pose -> force SH (docs/design.md, One frame, step 2).
#include "platform/runtime/patient_force.h"

namespace lungar::platform {

Eigen::Isometry3d registration_isometry(const std::array<double, 3>& translation_mm,
                                        const std::array<double, 4>& rotation_wxyz) {
  const auto& q = rotation_wxyz;
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  m.translation() = Eigen::Vector3d(translation_mm[0], translation_mm[1], translation_mm[2]);
  return m;
}

void patient_force_sh(const sim::BakedAsset& asset, const sim::PatientState& patient, sim::ForceMode mode,
                      const Eigen::Quaterniond& lung_in_world, std::span<float> force_out) {
  sim::force_sh(asset, patient, mode, lung_in_world, force_out.data());
}

}  // namespace lungar::platform
