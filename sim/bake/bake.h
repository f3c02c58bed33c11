/// @file bake.h
/// @brief Stages 2 and 3 offline: lung surfaces -> baked asset (transfer SH, linear basis, force bases, paper
///        arrays, truncated rows) and the report that measures it against the exact eq. (1).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/asset/baked_asset.h"
#include "config/base/result.h"
#include "sim/mesh/spherical_map.h"
#include "sim/motion/motion_figures.h"
#include "sim/motion/motion_model.h"
#include "sim/motion/surface_regions.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/transfer/transfer_rows.h"

namespace lungar::sim {

/// Bumped when a bake of the same inputs gives different output in the same file format, so that caches keyed by
/// it (the demo's, the benchmark's) bake again. 2: points in progressive Poisson-disk order (sim/mesh/lod_order.cpp).
/// 3: the SH fit on a one-to-one (conformal) spherical map instead of the radial one (sim/mesh/spherical_map.h).
/// 4: the sliding motion model by default (sim/motion/motion_model.h). 5: its apex slides and its costal face is
/// drawn down with the base (SlidingFaces::costal_slide).
inline constexpr std::uint32_t kBakeRevision = 5;

/// The tidal volume at which the volume normalisation is calibrated and the report measures (the paper's).
inline constexpr double kTidalVolumeMl = 500.0;

/// SH bands of a bake unless asked otherwise: 6 (36 coefficients), where the paper used 4 (16). On real lungs
/// eq. (7) needs 36 to stay under 1 % (the bands sweeps in docs/bake-measurements.md); 36 values are 9 vec4
/// vertex attributes, within GLES 3.0's 16 (render/shaders/deform.vert).
inline constexpr std::uint32_t kDefaultBands = 6;

struct BakeOptions {
  std::uint32_t bands = kDefaultBands;  ///< L, 1 to 8
  MotionModel model = MotionModel::sliding;  ///< sliding, or the paper's normal-only model
  SlidingFaces faces = default_sliding_faces();
  RegionRules regions;
  int threads = 0;                   ///< 0: all hardware threads
  double p0 = 10.0;                  ///< force model p = p0 + gamma g.(x - c)
  double gamma_per_mm = 0.025;
  double decay_length_mm = 10.0;     ///< tether length l
  bool transfer_rows = true;         ///< explicit truncated rows for the CPU eq. (1) baseline
  double transfer_epsilon = kTransferEpsilon;
  bool evaluate = true;              ///< fill the report's accuracy figures (26 gravity directions)
  bool bands_sweep = true;           ///< with evaluate: also solve all 8 bands' fields for the bands sweep
  SphereMapOptions sphere;           ///< the map u_I of the SH fit (eq. 7)
  /// With evaluate and bands_sweep: the other maps the report measures beside `sphere.map` (one more set of
  /// L^2 solves each, no effect on the asset).
  std::vector<SphereMap> compare_maps = {SphereMap::radial, SphereMap::conformal};
  /// When it turns true (lungar-bake's Ctrl-C), the bake stops at its next step and throws Cancelled
  /// (sim/parallel/parallel_for.h).
  const std::atomic<bool>* cancel = nullptr;
};

/// Called with a stage name ("factorise", "solve", "transfer rows", "evaluate") and that stage's fraction done;
/// calls are serialised.
using BakeProgress = std::function<void(std::string_view stage, double fraction)>;

/// One map's eq. (7) error at one band count (double precision, against the exact eq. 1).
struct MapError {
  SphereMap map = SphereMap::radial;
  double eq7_rms_rel_error = 0;
};

struct BandsSweepEntry {
  std::uint32_t bands = 0;
  std::uint32_t coefficients = 0;
  double eq7_rms_rel_error = 0;      ///< with the asset's map
  std::vector<MapError> by_map;      ///< the asset's map and each compared one
};

/// How one map places one lung (or all lungs, summed) on the sphere, and its fit at the asset's band count.
struct MapFigures {
  SphereMap map = SphereMap::radial;
  std::uint64_t folded_triangles = 0;
  double area_distortion = 0;        ///< RMS log area ratio (sim/mesh/spherical_map.h)
  double eq7_rms_rel_error = 0;
};

/// One lung's part of the report (`per_lung`).
struct LungReport {
  std::string name;
  std::uint32_t nodes = 0, triangles = 0;
  double volume_ml = 0;
  Eigen::Vector3d centroid_mm = Eigen::Vector3d::Zero();  ///< of the enclosed solid, LPS
  SphereMap map = SphereMap::radial;                     ///< the asset's
  std::uint64_t folded_triangles = 0;                    ///< under the asset's map
  double area_distortion = 0;
  double eq7_rms_rel_error = 0;                          ///< through the float asset, as the runtime computes it
  std::vector<MapFigures> maps;                          ///< the asset's map first, then the compared ones
  std::vector<BandsSweepEntry> bands_sweep;
  LungSource source;                                     ///< the import's figures (simplification, label map)
};

/// What a bake measures of its asset: size, timings, the sphere map, eq. (7), the linear basis and the truncated
/// rows against the exact eq. (1), and physiology (see sim/bake_tool/report_json.cpp for the JSON keys).
struct BakeReport {
  std::uint32_t nodes = 0, triangles = 0, lungs = 0, bands = 0, coefficients = 0;
  double transfer_nnz_per_row_mean = 0;
  double transfer_epsilon = 0;
  double bake_s = 0, sphere_map_s = 0, factorise_s = 0, solve_s = 0, transfer_rows_s = 0, evaluate_s = 0;
  SphereMap map = SphereMap::radial;   ///< the parameterisation of the SH fit
  std::uint64_t folded_triangles = 0;  ///< under `map`, all lungs
  double rest_volume_ml = 0;
  bool evaluated = false;
  double eq7_rms_rel_error = 0;
  double alpha = 0;
  double paper_interp_rms_rel_error = 0;
  double linear_basis_rms_rel_error = 0;
  double eq1_truncated_rms_rel_error = 0;   ///< the explicit truncated rows against the exact eq. (1)
  double displacement_max_mm_at_tidal = 0;
  double tidal_volume_rel_error = 0;        ///< (enclosed volume change at 500 mL - 500) / 500, signed
  double base_apex_displacement_ratio = 0;
  double posterior_anterior_displacement_ratio = 0;
  std::uint32_t gravity_directions = 0;
  std::vector<BandsSweepEntry> bands_sweep;
  std::vector<std::string> lung_names;
  std::vector<LungReport> per_lung;
  std::vector<MapFigures> maps;        ///< per map, all lungs: the asset's map first, then the compared ones
  /// The motion at kTidalVolumeMl (sim/motion/motion_figures.h): the asset's model through its float asset,
  /// supine, prone and upright; and the other model, exact, on the same lungs, for the side-by-side comparison.
  MotionModel model = MotionModel::sliding;
  double direction_rms_rel_error = 0;  ///< sliding: |u - e (e . u)| / |u| of the exact vector u (rank-one part)
  MotionFigures motion_supine, motion_prone, motion_upright;
  MotionModel compared_model = MotionModel::paper;
  MotionFigures compared_supine, compared_prone, compared_upright;
  /// The same figures, supine, on kInteriorReportPoints points inside the lungs moving with the harmonic extension
  /// of the surface's motion (sim/motion/interior_displacement.h), and that extension's grid step.
  MotionFigures interior_supine;
  std::size_t interior_points = 0;
  double interior_grid_mm = 0;
  /// How well the force SH and the linear basis carry each pathology's force (sim/force/dependent_collapse.h,
  /// CollapseFitError), per posture: "none" is the healthy linear pressure, which pneumothorax, consolidation and
  /// emphysema keep (they change the asset); "ards:0.6" the collapse that follows gravity.
  struct PatternFit {
    std::string pathology, posture;
    double sh_rms_rel_error = 0, linear_rms_rel_error = 0;
  };
  std::vector<PatternFit> pathology_force;
};

struct BakeOutput {
  BakedAsset asset;
  BakeReport report;
};

/// Bakes 1 to 16 closed, outward lung surfaces. Fails with one line naming the lung when a lung cannot be
/// baked (too few vertices for the bands, a singular stiffness). Throws Cancelled once options.cancel is set, and
/// passes on what a step throws (std::bad_alloc).
Result<BakeOutput> bake_lungs(std::vector<LungMesh> lungs, const BakeOptions& options, const BakeProgress& progress);

/// The default demo asset in-process: procedural_lungs(nodes, seed) baked with `options`.
Result<BakeOutput> bake_procedural(std::uint32_t nodes, std::uint64_t seed, const BakeOptions& options,
                                   const BakeProgress& progress);

/// The 26 unit gravity directions of the report: the cube's faces, edges and corners.
std::vector<Eigen::Vector3d> report_directions();

}  // namespace lungar::sim
