/// @file patient_force.h
/// @brief Frame-loop step 2: the patient tracker's pose and the registration -> gravity in the lung frame ->
/// force SH per lung. One function, shared by the frame loop and the hardware-in-the-loop tests.
#pragma once

#include <span>

#include <Eigen/Geometry>

#include "config/settings.h"
#include "sim/asset/baked_asset.h"
#include "sim/force/force_sh.h"

namespace lungar::platform {

/// The lung frame's orientation in the world: patient sensor -> world, after model -> patient sensor.
Eigen::Quaterniond lung_in_world(const Eigen::Quaterniond& patient_to_world, const Eigen::Quaterniond& registration);

/// Model -> patient-sensor rotation from the config's [registration].
Eigen::Quaterniond registration_rotation(const config::RegistrationSettings& r);

/// Force SH of every lung (lungs x L^2, lung-major) for a lung-frame orientation; allocates nothing.
void patient_force_sh(const sim::BakedAsset& asset, config::OrientationMode mode,
                      const Eigen::Quaterniond& lung_to_world, std::span<float> force_out);

}  // namespace lungar::platform
