/// @file mesh_import.h
/// @brief Real lung surfaces from STL (binary or ASCII), OBJ or PLY through assimp, for lungar-bake only.
#pragma once

#include <string>
#include <vector>

#include "config/base/result.h"
#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// Millimetres per unit of the file: "mm" 1, "cm" 10, "m" 1000; 0 for anything else.
double units_to_mm(const std::string& units);

/// Reads one or two files holding one or two lungs in all (one file with both lungs as two components, or one
/// file per lung), scales to mm, repairs what is safe (sim/mesh/mesh_repair.h) and names the lungs by side:
/// with two, the one at lower x (LPS) is the right lung; a single lung is "right" when its centroid has x < 0.
/// Repairs and choices are appended to `notes`.
Result<std::vector<LungMesh>> import_lungs(const std::vector<std::string>& files, double mm_per_unit,
                                           std::vector<std::string>& notes);

}  // namespace lungar::sim
