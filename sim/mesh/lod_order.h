/// @file lod_order.h
/// @brief Reorders a mesh's vertices so that every prefix is an even subsample of the surface (render/ draws
///        prefixes as levels of detail).
#pragma once

#include <cstdint>
#include <vector>

#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// A permutation (new position -> old index): coarse grid cells first, each refined level filling the cells
/// the earlier ones left empty. Deterministic.
std::vector<std::uint32_t> lod_order(const std::vector<Eigen::Vector3d>& positions);

/// Reorders `mesh`'s vertices by `order` (new -> old) and renumbers its triangles.
void reorder_vertices(TriMesh& mesh, const std::vector<std::uint32_t>& order);

}  // namespace lungar::sim
