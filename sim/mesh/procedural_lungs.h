/// @file procedural_lungs.h
/// @brief A deterministic, anatomically plausible pair of lung surfaces (LPS, mm) for demos and tests.
///
/// Each lung is a radial surface r(u) about a generating point (so it is star-shaped there; the bake uses the
/// volume centroid, a few mm away, and the radial map still folds nothing at the sizes tested): a tapered
/// ellipsoid with an apex, a concave diaphragmatic dome at the base, a concave medial face, and on the left
/// lung a cardiac notch; a few smooth seeded bumps make each seed a different patient. The right lung (at -x,
/// LPS) is the larger; volumes are exactly 2.7 L and 2.3 L.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

inline constexpr std::uint32_t kDefaultProceduralNodes = 400000;

/// Both lungs, right first, with about `total_nodes` vertices in all (at least 52). Same seed, same surfaces.
std::vector<LungMesh> procedural_lungs(std::uint32_t total_nodes, std::uint64_t seed);

}  // namespace lungar::sim
