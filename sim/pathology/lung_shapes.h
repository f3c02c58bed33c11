/// @file lung_shapes.h
/// @brief A change of pathologies while the lungs are drawn: the asset on the GPU stays the one loaded, and each
///        lung's new shape is an affine map of its loaded one (exact for the changes that move or scale a lung:
///        pneumothorax, its tension, emphysema) with its new figures (sim/patient/patient_state.h: its weight in the
///        split of the breath, its swept and rest volumes, its centre, an ARDS's collapse of its force). A
///        scenario's pathology events (a tension pneumothorax dropping, a needle decompression re-expanding it)
///        blend two such states over the event's time; the frame reads the blend as the patient now.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

/// One lung in one state of the pathologies.
struct LungShape {
  Eigen::Affine3d from_loaded = Eigen::Affine3d::Identity();  ///< loaded rest position -> this state's, lung frame
  LungState figures;                                          ///< the lung's figures in this state
};

/// Each lung of `changed` as a map of the same lung in `loaded` (the same bake, other pathologies), with its figures
/// in `changed_patient` (the state those pathologies left). An error names the lung whose change is not affine or
/// whose response changed (a consolidation: given for the whole run).
Result<std::vector<LungShape>> lung_shapes(const BakedAsset& loaded, const BakedAsset& changed,
                                           const PatientState& changed_patient);

/// `from` and `to` blended: w = 0 is `from`, 1 is `to` (the maps' matrices and the figures linearly; the healthy
/// volumes and the collapse, which do not blend, switch halfway).
std::vector<LungShape> blend(const std::vector<LungShape>& from, const std::vector<LungShape>& to, double w);

}  // namespace lungar::sim
