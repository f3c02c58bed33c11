/// @file tri_mesh.h
/// @brief A closed triangle surface of one lung in the lung frame (LPS, mm), and its per-vertex geometry.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sim/mesh/lung_source.h"

namespace lungar::sim {

using Triangle = std::array<std::uint32_t, 3>;

/// One lung's surface: shared vertices, counter-clockwise triangles seen from outside.
struct TriMesh {
  std::vector<Eigen::Vector3d> positions;  ///< mm, lung frame
  std::vector<Triangle> triangles;         ///< indices into positions
};

/// A lung surface with its name ("left"/"right") and, optionally, the centre it is star-shaped about.
struct LungMesh {
  std::string name;
  TriMesh mesh;
  bool has_centre = false;       ///< procedural lungs know their centre; imported ones use the volume centroid
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  LungSource source;             ///< filled by lungar-bake's import; the report carries it
};

/// Per-vertex geometry used by the bake (docs/design.md, "Transfer matrix": areas are a third of the incident
/// triangles' areas, normals are area-weighted and unit).
struct VertexGeometry {
  std::vector<double> areas;                 ///< A_I, mm^2
  std::vector<Eigen::Vector3d> normals;      ///< n_I, unit, outward for a positively oriented mesh
};

VertexGeometry vertex_geometry(const TriMesh& mesh);

/// Signed enclosed volume (divergence theorem), mm^3; positive when the triangles face outward.
double enclosed_volume(const TriMesh& mesh);

/// Enclosed volume of a flat index list (3 vertex indices a triangle, as a baked asset stores them) with vertex
/// positions `positions_xyz` (3 floats a vertex), mm^3.
double enclosed_volume(std::span<const std::uint32_t> triangle_indices, const float* positions_xyz);

/// Centroid of the enclosed solid (mm); needs a non-zero volume.
Eigen::Vector3d volume_centroid(const TriMesh& mesh);

/// Total surface area, mm^2.
double surface_area(const TriMesh& mesh);

/// Where the line along x through (y, z) crosses triangle `t` of `mesh`: its x, or nothing where (y, z) is outside
/// the triangle's (y, z) projection or the triangle is edge-on to x. Counting these crossings tells inside from
/// outside (the voxeliser's spans, the interior field's points).
std::optional<double> x_crossing(const TriMesh& mesh, std::uint32_t t, double y, double z);

}  // namespace lungar::sim
