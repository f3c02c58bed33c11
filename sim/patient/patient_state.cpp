/// @file patient_state.cpp
/// @brief The healthy state of an asset, and a lung's shape figures taken from it.
#include "sim/patient/patient_state.h"

namespace lungar::sim {

void LungState::take_shape_of(const BakedLung& lung) {
  centre = lung.centre;
  rest_volume_ml = lung.rest_volume_ml;
  volume_const = lung.volume_const;
  volume_grad = lung.volume_grad;
}

LungState LungState::healthy(const BakedLung& lung) {
  LungState state;
  state.take_shape_of(lung);
  return state;
}

PatientState PatientState::of(const BakedAsset& asset) {
  PatientState state;
  state.lungs.reserve(asset.lungs.size());
  for (const BakedLung& lung : asset.lungs) state.lungs.push_back(LungState::healthy(lung));
  return state;
}

}  // namespace lungar::sim
