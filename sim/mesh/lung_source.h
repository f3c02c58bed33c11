/// @file lung_source.h
/// @brief Where a lung's surface came from and what was done to it on the way in (the report's per_lung).
#pragma once

#include <cstdint>

namespace lungar::sim {

struct LungSource {
  std::uint32_t input_vertices = 0;  ///< of the surface before simplification (0: not known)
  bool simplified = false;
  double hausdorff_mm = 0;           ///< simplified surface against its input, when simplified
  bool from_label_map = false;       ///< the rest is about the label map's voxels
  bool rebuilt_from_voxels = false;  ///< or about the voxels of a surface that had handles
  long handles = 0;                  ///< of that surface, before
  std::int64_t label = 0;            ///< the label's value
  std::int64_t label_voxels = 0;     ///< voxels with that value
  double grid_mm = 0;                ///< the working grid's step
  std::int64_t components = 0;       ///< connected pieces of the label on the working grid
  std::int64_t removed_voxels = 0;   ///< in the pieces dropped (stray islands)
  std::int64_t filled_voxels = 0;    ///< added to close cavities and tunnels
  double removed_ml = 0, filled_ml = 0;
};

}  // namespace lungar::sim
