/// @file label_surface.h
/// @brief One lung's mask (a label of a CT label map) -> a closed, genus-0 surface in LPS millimetres.
///
/// The mask is averaged over blocks of voxels (a fraction inside per block), smoothed once with a [1 2 1] kernel,
/// sampled trilinearly onto a working grid as fine as the asked vertex count needs, thresholded at one half, made
/// a topological ball (sim/voxel/mask_topology.h), and its surface extracted by marching tetrahedra where the
/// smoothed fraction crosses the level that keeps the mask's volume (one half but for the smoothing's shrinkage
/// of convex parts) (sim/voxel/marching_tetrahedra.h), with the fraction clamped to the closed
/// mask's side at every grid point so the surface keeps the mask's topology. The averaging and the interpolation
/// between grid points take the CT's stair steps out.
#pragma once

#include <cstdint>

#include "config/base/result.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/voxel/mask_topology.h"
#include "sim/voxel/voxel_grid.h"

namespace lungar::sim {

struct LabelSurface {
  TriMesh mesh;                      ///< closed, outward, genus 0, LPS mm
  std::array<int, 3> block{1, 1, 1};  ///< mask voxels averaged per block along i, j, k
  double grid_mm = 0;                ///< the working grid's mean step
  MaskTopologyRepair repair;         ///< on the working grid
  double removed_ml = 0, filled_ml = 0;
};

/// The lung's surface with `target_vertices` to 5 % more vertices (the working grid's step is corrected up to
/// three times; else the nearest count above, or below on the mask's own grid); 0: from the mask's own grid.
/// `mask` needs at least one inside voxel; fails with one line when the lung is too small for any surface.
lungar::Result<LabelSurface> label_surface(const VoxelMask& mask, std::uint32_t target_vertices);

/// The mask's surface area estimated from its voxel faces (mm^2): the faces' area over 3/2, their mean excess
/// over a smooth surface of random orientation.
double mask_surface_area_mm2(const VoxelMask& mask);

}  // namespace lungar::sim
