/// @file freudenthal.h
/// @brief The Freudenthal (Kuhn) triangulation of the voxel grid: the one notion of "connected" and "hole" that
///        the label-map pipeline uses, from the mask's components to the extracted surface.
///
/// Each grid cube is cut into 6 tetrahedra along its main diagonal, so a grid point has 14 neighbours (the 6
/// faces, 6 of the 12 edge diagonals and 2 of the 8 corner diagonals: the offsets d with d or -d in {0,1}^3).
/// Marching tetrahedra on this triangulation always gives a closed 2-manifold whose topology is exactly that of
/// the full subcomplex spanned by the inside points, and a point is "simple" (adding or removing it keeps that
/// topology) when the inside part and the outside part of its link, a triangulated sphere of 14 points, are
/// both non-empty and connected (Alexander duality on the sphere). One lookup of a 14-bit pattern decides it.
#pragma once

#include <array>
#include <cstdint>

namespace lungar::sim {

/// The 14 neighbour offsets of a grid point.
inline constexpr std::array<std::array<int, 3>, 14> kFreudenthalOffsets = {{
    {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 0},
    {-1, -1, 0}, {1, 0, 1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, -1}, {1, 1, 1}, {-1, -1, -1},
}};

/// The 7 edge directions with non-negative components; every grid edge is p -> p + one of them.
inline constexpr std::array<std::array<int, 3>, 7> kFreudenthalEdges = {{
    {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1},
}};

/// Whether a point whose 14 neighbours are inside where `pattern` has a 1 (bit n: kFreudenthalOffsets[n]) is
/// simple: flipping it between inside and outside keeps the topology of the inside and of the outside.
bool is_simple_point(std::uint16_t pattern);

}  // namespace lungar::sim
