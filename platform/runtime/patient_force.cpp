/// @file patient_force.cpp
/// @brief Patient pose -> force SH (DESIGN.md, frame step 2).
#include "platform/runtime/patient_force.h"

#include "sim/force/force_sh.h"

namespace lungar::platform {

Eigen::Isometry3d registration_isometry(const config::RegistrationSettings& r) {
  const auto& q = r.rotation_wxyz;
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  m.translation() = Eigen::Vector3d(r.translation_mm[0], r.translation_mm[1], r.translation_mm[2]);
  return m;
}

void patient_force_sh(const sim::BakedAsset& asset, config::OrientationMode mode,
                      const Eigen::Quaterniond& lung_in_world, std::span<float> force_out) {
  const sim::ForceMode m = mode == config::OrientationMode::Exact ? sim::ForceMode::exact : sim::ForceMode::paper;
  sim::force_sh(asset, m, lung_in_world, force_out.data());
}

}  // namespace lungar::platform
