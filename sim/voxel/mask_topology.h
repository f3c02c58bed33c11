/// @file mask_topology.h
/// @brief Makes a lung mask a topological ball in voxel space, so that its surface is one genus-0 sphere: the
///        largest component is kept (stray islands dropped), then every cavity and tunnel is closed.
///
/// Real segmentations have holes: a bubble inside (a cavity), a vessel bored through (a tunnel, i.e. a handle of
/// the surface). The closing grows the outside inwards from the grid's border one simple point at a time
/// (sim/voxel/freudenthal.h), farthest from the lung first, so the outside stays a ball's complement: where it
/// would meet itself round a tunnel it stops, and the voxels it never reaches (the lung, its cavities and a thin
/// membrane across each tunnel) become the closed lung. The two blind pits a membrane leaves are then filled too
/// (a closing as wide as the membrane, kept where it touches it), since a conformal map crushes deep pits.
#pragma once

#include <cstdint>

#include "sim/voxel/voxel_grid.h"

namespace lungar::sim {

struct MaskTopologyRepair {
  std::int64_t components = 0;      ///< connected pieces of the mask before (Freudenthal connectivity)
  std::int64_t removed_voxels = 0;  ///< in the pieces dropped
  std::int64_t filled_voxels = 0;   ///< added to close cavities and tunnels (membranes and the tunnels' pits)
};

/// Keeps the largest connected piece and closes it to a ball. The grid's outermost layer must be outside.
MaskTopologyRepair close_to_ball(VoxelMask& mask);

/// Connected pieces of the inside (Freudenthal connectivity); the grid's outermost layer must be outside.
std::int64_t count_components(const VoxelMask& mask);

}  // namespace lungar::sim
