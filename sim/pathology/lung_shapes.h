/// @file lung_shapes.h
/// @brief A change of pathologies while the lungs are drawn: the asset on the GPU stays the one loaded, and each
///        lung's new shape is an affine map of its loaded one (exact for the changes that move or scale a lung:
///        pneumothorax, its tension, emphysema) with its new figures (its weight in the split of the breath, its
///        swept and rest volumes, its centre, an ARDS's collapse of its force). A scenario's pathology events (a tension pneumothorax dropping, a
///        needle decompression re-expanding it) blend two such states over the event's time.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"

namespace lungar::sim {

/// The per-lung figures of BakedLung that a pathology changes and the force and the split read.
struct LungFigures {
  std::array<float, 3> centre{};
  double rest_volume_ml = 0;
  double volume_const = 0;
  std::array<double, 3> volume_grad{};
  double breath_weight = 1;
  std::optional<std::array<double, 4>> healthy_volumes;
  std::shared_ptr<const DependentCollapse> collapse;  ///< an ARDS: a change of the force, not of the response
  std::size_t collapse_index = 0;

  static LungFigures of(const BakedLung& lung);
  void put_into(BakedLung& lung) const;
};

/// One lung in one state of the pathologies.
struct LungShape {
  Eigen::Affine3d from_loaded = Eigen::Affine3d::Identity();  ///< loaded rest position -> this state's, lung frame
  LungFigures figures;
};

/// Each lung of `changed` as a map of the same lung in `loaded` (the same bake, other pathologies). An error names
/// the lung whose change is not affine or whose response changed (a consolidation: given for the whole run).
Result<std::vector<LungShape>> lung_shapes(const BakedAsset& loaded, const BakedAsset& changed);

/// `from` and `to` blended: w = 0 is `from`, 1 is `to` (the maps' matrices and the figures linearly; the healthy
/// volumes and the collapse, which do not blend, switch halfway).
std::vector<LungShape> blend(const std::vector<LungShape>& from, const std::vector<LungShape>& to, double w);

/// Sets each lung's figures of `asset` to those of `shapes` (the positions stay: the map is the drawing's).
void take_figures(const std::vector<LungShape>& shapes, BakedAsset& asset);

}  // namespace lungar::sim
