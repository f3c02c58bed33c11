/// @file mesh_repair.h
/// @brief Turns a raw triangle soup (from any importer) into closed, consistently oriented lung surfaces.
///
/// Safe repairs are made and said in `notes` (equal corners welded, degenerate triangles dropped, orientation
/// made consistent and outward, unused vertices removed, tiny stray components dropped); anything unsafe
/// (non-finite coordinates, open or non-manifold surfaces, too few triangles) is one error line naming `source`.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"
#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// Cleans `soup` (vertices may repeat; indices must be < positions.size()) and splits it into its connected
/// components, largest first. Every returned mesh is closed, 2-manifold and outward-facing.
Result<std::vector<TriMesh>> repair_surface(const TriMesh& soup, const std::string& source,
                                            std::vector<std::string>& notes);

}  // namespace lungar::sim
