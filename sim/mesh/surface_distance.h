/// @file surface_distance.h
/// @brief How far apart two surfaces are: the Hausdorff distance the bake reports when it simplifies a lung.
#pragma once

#include "sim/mesh/tri_mesh.h"
#include "sim/parallel/parallel_for.h"

namespace lungar::sim {

/// The symmetric Hausdorff distance (mm) between surfaces a and b, measured from every vertex of each to the
/// nearest point of the other's triangles (exact point-to-triangle distances through a bounding-volume tree).
/// Sampling at vertices can miss a farther point inside a triangle; for the fine inputs lungar simplifies,
/// whose vertices are denser than the simplified triangles, that is where the far points are.
double hausdorff_mm(const TriMesh& a, const TriMesh& b, const Workers& workers);

}  // namespace lungar::sim
