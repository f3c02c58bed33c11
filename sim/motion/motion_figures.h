/// @file motion_figures.h
/// @brief The figures that hold lung motion against 4-D CT: superior-inferior share, apex : base, dorsal :
///        ventral, mean displacement, and each surface face's share of the motion.
///
/// Definitions (those of DIR-Lab's landmark figures, docs/design.md, "Vector displacement"), over every vertex of
/// every lung (or every interior point, sim/motion/interior_displacement.h) with its displacement d from rest, in
/// the lung frame (LPS):
///   si_share              mean |d_z| / mean |d|
///   apex_base_ratio       mean |d| of the top third of the vertices by rest height over the bottom third
///   dorsal_ventral_ratio  mean |d| of the back third by rest depth (+y) over the front third
/// A face's volume share is its part of the first-order swept volume, sum A_I (d_I . n_I).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "sim/asset/baked_asset.h"
#include "sim/motion/surface_regions.h"
#include "sim/patient/patient_state.h"

namespace lungar::sim {

struct RegionMotion {
  double area_mm2 = 0;
  double area_share = 0;
  double volume_share = 0;          ///< of the swept volume
  double mean_displacement_mm = 0;  ///< mean |d| over its vertices
};

struct MotionFigures {
  double si_share = 0;              ///< superior-inferior: mean |d_z| / mean |d| (4-D CT: about 0.9)
  double apex_base_ratio = 0;       ///< mean |d| at the apex over at the base (< 1: the base moves most)
  double dorsal_ventral_ratio = 0;  ///< mean |d| at the back over at the front
  double mean_displacement_mm = 0;  ///< mean |d| over every vertex
  double max_displacement_mm = 0;   ///< the largest |d|
  std::array<RegionMotion, kSurfaceRegionCount> regions{};  ///< indexed by SurfaceRegion; empty without regions
};

/// The figures of displacements `d` (3 per vertex, mm) of `asset`'s vertices; `regions` (one per vertex, or
/// empty) adds the per-face figures.
MotionFigures motion_figures(const BakedAsset& asset, std::span<const float> d,
                             const std::vector<SurfaceRegion>& regions);

/// The same figures, without faces, of displacements `d` (3 per point, mm) of points at rest positions `rest`
/// (3 per point, mm, LPS): the interior points' (`interior_*` in the bake report).
MotionFigures point_motion_figures(std::span<const float> rest, std::span<const float> d);

/// The displacement of every vertex of `asset` (3 per vertex, mm) when the pair's volume changes by
/// `delta_volume_ml` with lung-frame gravity `g`, the patient as `patient` is, by eq. (7) in the exact orientation
/// mode, as the runtime draws it.
std::vector<float> displacement_vectors(const BakedAsset& asset, const PatientState& patient, const Eigen::Vector3d& g,
                                        double delta_volume_ml);

}  // namespace lungar::sim
