/// @file marching_tetrahedra.h
/// @brief The surface of a lung from a field sampled on its voxel grid: marching tetrahedra on the Freudenthal
///        triangulation (sim/voxel/freudenthal.h), which, unlike marching cubes, has no ambiguous case, so the
///        surface is always a closed 2-manifold with the topology of the inside points.
#pragma once

#include <vector>

#include "sim/mesh/tri_mesh.h"
#include "sim/voxel/voxel_grid.h"

namespace lungar::sim {

/// The surface {field = 0}, positive inside, in the grid's frame (LPS, mm), triangles facing outward. Every value
/// must be non-zero and the grid's outermost layer negative. A vertex sits on each grid edge whose ends differ in
/// sign, at the linear zero crossing kept within [0.05, 0.95] of the edge (moving a vertex along its own edge keeps
/// the surface embedded, and the margin keeps its triangles from degenerating).
TriMesh marching_tetrahedra(const VoxelGrid& grid, const std::vector<float>& field);

}  // namespace lungar::sim
