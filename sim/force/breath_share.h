/// @file breath_share.h
/// @brief Each lung's share of the pair's breath in a posture: the dependent lung takes more.
///
/// Awake and breathing on their own, people lying on one side ventilate the lower (dependent) lung more: the
/// abdomen pushes its hemidiaphragm up into a longer, more curved start, so it moves further with each breath
/// (docs/design.md, "Posture and the split between the lungs"). Upright, supine and prone the lungs sit side by
/// side across gravity and the split stays their rest-volume split.
///
/// The model: lung l's weight is its rest-volume share V_l times (1 + k d_l), where d_l = g . u_l is how far it
/// lies down the gravity direction g (unit, lung frame), u_l the unit vector from the pair's volume-weighted centre
/// to the lung's centre; the shares are the weights over their sum, so the pair's volume change stays dV exactly.
/// k = kDependentLungGain is set once against electrical impedance tomography of awake adults in lateral
/// decubitus (the dependent lung took 57.6 % left side down and 64.7 % right side down, 10 subjects): with the
/// CT demo's 47 : 53 rest split it gives 58 % and 64 %.
#pragma once

#include <cstddef>

#include <Eigen/Core>

#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

/// k of the model above: how much more than its volume share a lung takes when it lies straight down-gravity.
inline constexpr double kDependentLungGain = 0.22;

/// Lung `lung`'s share of the pair's volume change with gravity `g_lung` (lung frame; normalised here); the shares
/// of all lungs sum to 1. One lung: 1 (its rest-volume share). A zero or non-finite g: the split without the
/// posture term. The centres are the lungs' now (`patient`), and each weight also carries the lung's pathology
/// factors there (LungState::breath_weight, and V(g) / V_healthy(g) when a pathology changed its response).
double breath_share(const BakedAsset& asset, const PatientState& patient, std::size_t lung,
                    const Eigen::Vector3d& g_lung);

}  // namespace lungar::sim
