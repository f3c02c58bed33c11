/// @file surface_simplify.h
/// @brief Fewer vertices for a closed lung surface, for lungar-bake only (OpenMesh's decimater).
///
/// Why OpenMesh (Debian's libopenmesh-dev, BSD licence, RWTH Aachen, maintained since 2001): its decimater
/// collapses edges in quadric-error order (Garland & Heckbert) and refuses every collapse that fails the link
/// condition, so a closed 2-manifold stays closed, manifold and of the same genus, which the spherical map
/// needs; binary modules refuse collapses that flip a normal or make a sliver. meshoptimizer (MIT, tiny) is
/// faster but does not guarantee manifold output; CGAL's edge collapse would do, but is GPL for this use and
/// heavy to build.
#pragma once

#include <cstdint>

#include "config/base/result.h"
#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// `mesh` (closed, 2-manifold, outward) simplified to `target` vertices, or as near as the collapses that keep
/// its quality allow; fails with one line when OpenMesh cannot take the surface in.
lungar::Result<TriMesh> simplify_surface(const TriMesh& mesh, std::uint32_t target);

}  // namespace lungar::sim
