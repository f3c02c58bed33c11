/// @file bake.h
/// @brief Stages 2 and 3 offline: lung surfaces -> baked asset (transfer SH, linear basis, force bases, paper
///        arrays, truncated rows) and the report that measures it against the exact eq. (1).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/asset/baked_asset.h"
#include "config/base/result.h"
#include "sim/mesh/tri_mesh.h"
#include "sim/transfer/transfer_rows.h"

namespace lungar::sim {

/// Bumped when a bake of the same inputs gives different output in the same file format, so that caches keyed by
/// it (the demo's, the benchmark's) bake again. 2: points in progressive Poisson-disk order (sim/mesh/lod_order.cpp).
inline constexpr std::uint32_t kBakeRevision = 2;

/// The tidal volume at which the volume normalisation is calibrated and the report measures (the paper's).
inline constexpr double kTidalVolumeMl = 500.0;

struct BakeOptions {
  std::uint32_t bands = 4;           ///< L, 1 to 8
  int threads = 0;                   ///< 0: all hardware threads
  double p0 = 10.0;                  ///< force model p = p0 + gamma g.(x - c)
  double gamma_per_mm = 0.025;
  double decay_length_mm = 10.0;     ///< tether length l
  bool transfer_rows = true;         ///< explicit truncated rows for the CPU eq. (1) baseline
  double transfer_epsilon = kTransferEpsilon;
  bool evaluate = true;              ///< fill the report's accuracy figures (26 gravity directions)
  bool bands_sweep = true;           ///< with evaluate: also solve all 8 bands' fields for the bands sweep
};

/// Called with a stage name ("factorise", "solve", "transfer rows", "evaluate") and that stage's fraction done;
/// calls are serialised.
using BakeProgress = std::function<void(std::string_view stage, double fraction)>;

struct BandsSweepEntry {
  std::uint32_t bands = 0;
  std::uint32_t coefficients = 0;
  double eq7_rms_rel_error = 0;
};

/// The figures of issue 3's report (see sim/bake_tool/report_json.cpp for the JSON keys).
struct BakeReport {
  std::uint32_t nodes = 0, triangles = 0, lungs = 0, bands = 0, coefficients = 0;
  double transfer_nnz_per_row_mean = 0;
  double transfer_epsilon = 0;
  double bake_s = 0, factorise_s = 0, solve_s = 0, transfer_rows_s = 0, evaluate_s = 0;
  std::uint64_t folded_triangles = 0;
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
};

struct BakeOutput {
  BakedAsset asset;
  BakeReport report;
};

/// Bakes 1 to 16 closed, outward lung surfaces. Fails with one line naming the lung when a lung cannot be
/// baked (too few vertices for the bands, a singular stiffness).
Result<BakeOutput> bake_lungs(std::vector<LungMesh> lungs, const BakeOptions& options, const BakeProgress& progress);

/// The default demo asset in-process: procedural_lungs(nodes, seed) baked with `options`.
Result<BakeOutput> bake_procedural(std::uint32_t nodes, std::uint64_t seed, const BakeOptions& options,
                                   const BakeProgress& progress);

/// Triangles whose radial-map image u = (x - c)/|x - c| is folded (not positively oriented on the sphere).
std::uint64_t folded_triangles(const TriMesh& mesh, const Eigen::Vector3d& centre);

/// The 26 unit gravity directions of the report: the cube's faces, edges and corners.
std::vector<Eigen::Vector3d> report_directions();

}  // namespace lungar::sim
