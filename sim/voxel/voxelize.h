/// @file voxelize.h
/// @brief The voxels inside a closed triangle surface: how a surface with handles (a raw segmentation export) is
///        taken back to a mask, closed to a ball in voxel space and extracted again as a genus-0 surface
///        (sim/voxel/label_surface.h).
#pragma once

#include "sim/mesh/tri_mesh.h"
#include "sim/voxel/voxel_grid.h"

namespace lungar::sim {

/// The surface's voxels on an axis-aligned grid of step `spacing_mm` covering it with a margin: a voxel is inside
/// when a ray along +x from its centre crosses the surface an odd number of times (the surface must be closed;
/// its orientation does not matter).
VoxelMask voxelize(const TriMesh& mesh, double spacing_mm);

/// A grid step for voxelising `mesh`: its mean edge length, coarsened when the grid would pass `max_voxels`.
double voxel_step_for(const TriMesh& mesh, double max_voxels = 8e7);

}  // namespace lungar::sim
