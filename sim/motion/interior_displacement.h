/// @file interior_displacement.h
/// @brief The displacement inside the lungs: the harmonic extension of each lung's surface displacement into its
///        volume, on a grid, and points sampled uniformly from the lungs' volume to carry it (a tumour, the
///        landmarks 4-D CT's figures are measured on).
///
/// Why harmonic (docs/design.md, "Motion inside the lung"): the interior of a lung has no force of its own in the
/// model, only the motion its surface imposes (the diaphragm pulls the base down, the ribs and the mediastinum
/// hold the rest). The field u with u = the surface's displacement on the surface and Laplace's equation
/// div grad u = 0 inside is the one that minimises the Dirichlet energy, the integral of |grad u|^2: the smoothest
/// interior motion that agrees with the surface, which is also the diffusion regulariser deformable registration
/// of 4-D CT uses to produce the interior motion DIR-Lab's landmarks are compared with. So a point near the
/// diaphragm moves nearly as the diaphragm does and one near the hilum as little as the hilum does; no interior
/// point moves farther than the surface (the maximum principle, per component); and the field is linear in the
/// surface's displacement. That last property is what lets the runtime evaluate it the paper's way: an interior
/// point's displacement is sum_I E(p, I) d_I, so its coefficient rows are the same sum over the surface vertices'
/// SH rows (T^p_lm = sum_I E(p, I) T^I_lm e_I, and likewise the off-axis basis): baked once per point, evaluated
/// in the vertex shader as a dot product with the force SH like a surface vertex's.
///
/// Discretisation: each lung on its own axis-aligned grid of step h. Grid nodes inside the surface (ray parity,
/// sim/voxel/voxelize.h) are the unknowns of the 7-point Laplacian; every outside node next to them (26
/// neighbours) is a boundary node holding the displacement of the surface point nearest to it (barycentric in
/// that triangle's vertices), as Joshi et al. compute harmonic coordinates on a grid (Harmonic Coordinates for
/// Character Articulation, SIGGRAPH 2007). The discrete solution is a weighted mean of its neighbours at every
/// unknown, so the discrete maximum principle holds exactly; a point between nodes is interpolated trilinearly
/// (a convex combination again). The surface is met to within O(h).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "sim/asset/baked_asset.h"
#include "sim/motion/motion_figures.h"

namespace lungar::sim {

/// One surface vertex's weight in the displacement of a point inside a lung (InteriorDisplacement::surface_weights).
struct VertexWeight {
  std::uint32_t vertex = 0;  ///< the asset's vertex index
  double weight = 0;
};

/// Points inside the lungs, at rest.
struct InteriorPoints {
  std::vector<float> positions;             ///< 3 per point, mm, lung frame (LPS)
  std::vector<std::uint8_t> lung_of_point;  ///< index into the asset's lungs
  std::size_t size() const { return lung_of_point.size(); }
};

/// The seed of the interior points the bake report and `lungar-bake export --interior` sample, so that the same
/// N gives the same points (and the same figures) in both.
inline constexpr std::uint64_t kInteriorSeed = 1;

/// Interior points the bake report's `interior_*` figures are measured on (4-D CT's landmark count is 300 a
/// case; 5,000 keeps the tertiles' means within about 1 % of the volume's).
inline constexpr std::size_t kInteriorReportPoints = 5000;

/// The harmonic extension of a surface displacement into the lungs of one asset: the grids, their boundary nodes'
/// nearest surface points and the Laplacians, built once from the rest surface; then, for any displacement of the
/// surface's vertices, the displacement of any point inside a lung.
class InteriorDisplacement {
 public:
  /// Grids for every lung of `asset` (its rest surface: positions, triangles, lungs' ranges) at step `spacing_mm`,
  /// or, for 0, a step that puts about kAutoNodes grid nodes inside the lungs (at least 1 mm).
  explicit InteriorDisplacement(const BakedAsset& asset, double spacing_mm = 0);
  ~InteriorDisplacement();
  InteriorDisplacement(InteriorDisplacement&&) noexcept;
  InteriorDisplacement& operator=(InteriorDisplacement&&) noexcept;

  /// Grid nodes inside the lungs for an automatic step: enough for the figures (about 3 mm on an adult pair),
  /// few enough that a solve takes a second or two on two cores.
  static constexpr double kAutoNodes = 120000;

  double spacing_mm() const { return spacing_; }
  /// Grid nodes inside lung `lung` (the unknowns of its Laplacian).
  std::size_t inside_nodes(std::size_t lung) const;

  /// The lung whose surface encloses p (ray parity), or -1 when none does.
  int lung_containing(const Eigen::Vector3d& p) const;

  /// `count` points uniform over the lungs' volume (each lung gets its share by volume, by chance): rejection
  /// sampling in the box around all lungs, from a 64-bit Mersenne twister seeded with `seed`. The same asset,
  /// count and seed give the same points on every machine.
  InteriorPoints sample(std::size_t count, std::uint64_t seed = kInteriorSeed) const;

  /// The displacement (3 per point, mm) at `points` (each inside its lung) when the asset's vertices move by
  /// `surface_d` (3 per vertex, mm): per lung, Laplace's equation solved with the surface as its boundary, then
  /// interpolated. Linear in surface_d.
  std::vector<float> displacement(std::span<const float> surface_d, const InteriorPoints& points) const;

  /// The weights E(p, I) of the point p inside lung `lung`: for every surface displacement d, displacement() at p
  /// is sum_I E(p, I) d_I (the field is linear in d). One adjoint solve: p's value is a' u + beta' b with a, beta
  /// its trilinear weights on the inside and boundary nodes and u = L^-1 C b, so its weights on the boundary
  /// values are C' L^-1 a + beta (L is symmetric), spread onto the vertices by each boundary node's barycentric
  /// weights. They sum to 1 (a uniform motion of the surface moves every inside point alike) and are all >= 0 up
  /// to the solver's tolerance (the discrete maximum principle). Only non-zero weights are returned, by vertex.
  std::vector<VertexWeight> surface_weights(const Eigen::Vector3d& p, std::size_t lung) const;

 private:
  struct Lung;
  double spacing_ = 0;
  std::vector<std::unique_ptr<Lung>> lungs_;
};

}  // namespace lungar::sim
