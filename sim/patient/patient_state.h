/// @file patient_state.h
/// @brief What the patient is now, beside the baked asset that says how its lungs respond: each lung's figures
///        that a pathology or a scenario's course changes (its centre, rest and swept volumes, its weight in the
///        split of the breath, an ARDS's collapse of its force). The asset is loaded once and never written again;
///        the state is a value that load-time pathologies set (sim/pathology/pathology.h), a course replaces every
///        frame (sim/pathology/lung_shapes.h) and the force, the split and the CPU paths read (sim/force/).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "sim/asset/baked_asset.h"

namespace lungar::sim {

class DependentCollapse;

/// One lung now. The first four start as the asset's (BakedLung) and follow the lung's shape; the rest are the
/// pathologies' and start healthy.
struct LungState {
  std::array<float, 3> centre{};        ///< c, the SH centre, mm in the lung frame
  double rest_volume_ml = 0;            ///< enclosed volume at rest
  double volume_const = 0;              ///< v0 of the swept volume V(g) = p0 v0 + gamma g.v
  std::array<double, 3> volume_grad{};  ///< v
  /// A pathology's factor on the lung's weight in the split of the breath (sim/force/breath_share.h): 1 when healthy.
  double breath_weight = 1.0;
  /// v0 and v before a pathology changed the lung's response: the lung's weight in the split then also carries
  /// V(g) / V_healthy(g), the part of its healthy breath its surface can still take in the posture, so that what
  /// is left of the lung breathes as before.
  std::optional<std::array<double, 4>> healthy_volumes;
  /// An ARDS: the force that follows the posture, which replaces the linear pressure's in force_sh.h for this
  /// lung, `collapse_index` its index there (sim/force/dependent_collapse.h).
  std::shared_ptr<const DependentCollapse> collapse;
  std::size_t collapse_index = 0;

  /// The lung's shape figures taken from `lung` (the four above the pathologies'), the rest kept.
  void take_shape_of(const BakedLung& lung);
  /// `lung` healthy: its baked figures, weight 1, no collapse.
  static LungState healthy(const BakedLung& lung);
};

/// The patient now: one LungState per lung of the asset it goes with, in the asset's order.
struct PatientState {
  std::vector<LungState> lungs;

  /// The healthy patient of `asset`: its lungs' baked figures, weight 1, no collapse.
  static PatientState of(const BakedAsset& asset);
};

}  // namespace lungar::sim
