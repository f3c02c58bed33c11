/// @file spherical_map.h
/// @brief Where each vertex of a lung surface sits on the unit sphere, for the SH fit of eq. (7) (docs/design.md,
///        "SH deformation (eq. 7)").
///
/// The paper's radial map u = (x - c)/|x - c| folds wherever the surface is not star-shaped about c (a real
/// lung's hilar face), so the force is not a function on the sphere there. The conformal map here is the
/// paper's "conformal mapping" future work, done as Choi, Lam & Lui's fast spherical conformal map (2015) does
/// it: puncture the genus-0 surface at its largest triangle, solve one sparse cotangent (Tutte) embedding of the
/// rest into that triangle in the plane, lift it by inverse stereographic projection, then a Moebius
/// transformation puts the surface's area centroid at the sphere's centre. Positive edge weights and a convex
/// boundary make the plane embedding one-to-one (Tutte, Floater), and both lifts preserve orientation, so no
/// triangle folds (counted, to be sure). On a real lung it fits eq. (7) better than the radial map, which folds
/// its hilar face (docs/bake-measurements.md).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "config/base/enum_names.h"
#include "config/base/result.h"
#include "sim/mesh/tri_mesh.h"

namespace lungar::sim {

/// The parameterisation of a lung surface on the unit sphere.
enum class SphereMap : std::uint8_t {
  radial,     ///< u = (x - c)/|x - c|: the paper's; folds on surfaces not star-shaped about c
  conformal,  ///< angle-preserving, Moebius-balanced: one-to-one on any genus-0 surface; the default
};

/// The names of the maps: the report's `map`, lungar-bake's --map.
inline constexpr EnumNames<SphereMap, 2> kSphereMapNames{
    {{{SphereMap::radial, "radial"}, {SphereMap::conformal, "conformal"}}}};

struct SphereMapOptions {
  SphereMap map = SphereMap::conformal;
};

struct SphereMapResult {
  std::vector<Eigen::Vector3d> u;   ///< unit vectors, one per vertex
  std::uint64_t folded = 0;         ///< triangles not positively oriented on the sphere (0 for the one-to-one maps)
  double area_distortion = 0;       ///< RMS over the surface's area of log(sphere area share / surface area share)
};

/// Maps `mesh` (closed, outward, genus 0 for the one-to-one maps) onto the unit sphere; `centre` is c of the
/// radial map. Fails with one line when a one-to-one map is asked of a surface that is not genus 0.
lungar::Result<SphereMapResult> map_to_sphere(const TriMesh& mesh, const Eigen::Vector3d& centre, const SphereMapOptions& options);

/// Triangles whose images (a, b, c) on the unit sphere are not positively oriented, det(a, b, c) <= 0.
std::uint64_t folded_on_sphere(const TriMesh& mesh, const std::vector<Eigen::Vector3d>& u);

/// V - E + F of a closed triangle surface (2 for a sphere; 2 - 2g with g handles).
long euler_characteristic(const TriMesh& mesh);

}  // namespace lungar::sim
