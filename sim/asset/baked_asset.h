/// @file baked_asset.h
/// @brief The in-memory form of a `.lungbake` asset: what `lungar-bake` produces and the runtime draws.
///
/// All lungs share one vertex array; each lung owns a contiguous range of it. Per vertex the asset holds the
/// rest position, the outward unit normal, the lung it belongs to, and the SH coefficients of its transfer-matrix
/// row, T^I_lm = sum_J T(I,J) A_J Y_lm(u_J) (docs/design.md, "SH deformation (eq. 7)"), in mm per (unit force
/// SH), and the direction the vertex moves along — the vertex shader computes D = dV * sum_lm T^I_lm f_lm and
/// moves the vertex by D along that direction: its normal in the paper's model, the principal direction of its
/// baked vector displacement in the sliding model (sim/motion/motion_model.h).
///
/// Vertices are stored in level-of-detail order: every prefix of a lung's range is an even subsample of its
/// surface (render/ draws prefixes).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sim/motion/motion_model.h"

namespace lungar::sim {

/// Orientation angles of the paper's eq. (8)-(9): pi/2, pi, 3pi/2, 2pi about each of X, Y, Z.
inline constexpr int kPaperAxes = 3;
inline constexpr int kPaperAngles = 4;

/// One lung of the asset.
struct BakedLung {
  std::string name;                      ///< "left" or "right" (LPS: +x is the patient's left)
  std::array<float, 3> centre{};         ///< c, the SH centre, mm in the lung frame
  std::uint32_t first_vertex = 0;        ///< range in BakedAsset's vertex arrays
  std::uint32_t vertex_count = 0;
  std::uint32_t first_index = 0;         ///< range in BakedAsset::triangles (3 indices a triangle)
  std::uint32_t index_count = 0;
  double rest_volume_ml = 0;             ///< enclosed volume at rest

  /// Exact orientation mode (docs/design.md, "Orientation"): unnormalised force SH f(g) = p0 f0 + gamma sum_k
  /// g_k f_k, and the swept volume of the displacement it produces, V(g) = p0 v0 + gamma g.v (mm^3); the runtime
  /// force is f(g) * 1000/V(g), so that the displacement is in mm per mL of volume change.
  std::vector<float> force_const;                 ///< f0, L^2 values
  std::array<std::vector<float>, 3> force_grad;   ///< f_x, f_y, f_z, L^2 values each
  /// v0 and v are the first-order swept volumes sum_I A_I (e_I . n_I) D_I scaled by one factor per lung (about
  /// 1.03) so that, upright, dV = 500 mL changes the enclosed volume by exactly 500 mL (secant at the tidal
  /// volume, which absorbs the surface-curvature term the first-order sum leaves out).
  double volume_const = 0;                        ///< v0
  std::array<double, 3> volume_grad{};            ///< v

  /// The paper's eq. (8)-(9): normalised force SH at rotations pi/2, pi, 3pi/2, 2pi about X, Y and Z of the
  /// upright patient; index [axis * kPaperAngles + angle][lm].
  std::vector<std::vector<float>> paper_force;

  /// This lung's share of the pair's rest volume (the shares sum to 1). The breathing driver's dV(t) is the pair's
  /// volume change; each lung sweeps dV times its share of the breath in the posture, which starts from this one
  /// and tilts towards the dependent lung (sim/force/breath_share.h); the runtime multiplies the lung's force SH by
  /// it, and sim/deform does so for the CPU paths.
  double volume_share = 1.0;
};

/// The largest radius a lesion may have: a 10 cm mass is already larger than the tumours radiotherapy tracks.
inline constexpr double kMaxLesionRadiusMm = 50.0;
inline constexpr std::size_t kMaxLesionNameLength = 32;

/// A lesion's name: 1 to kMaxLesionNameLength letters, digits, '_' or '-' (it goes into file names and JSON keys).
inline bool lesion_name_ok(std::string_view name) {
  if (name.empty() || name.size() > kMaxLesionNameLength) return false;
  for (unsigned char c : name)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '-'))
      return false;
  return true;
}

/// A lesion baked with the lungs (`lungar-bake --lesion`): a ball inside one lung, which the runtime draws and moves
/// with the interior field (sim/motion/lesion_rows.h) as it does one given at run time.
struct BakedLesion {
  std::string name;                   ///< 1 to 32 letters, digits, '_' or '-'
  std::uint32_t lung = 0;             ///< index into BakedAsset::lungs
  std::array<double, 3> centre_mm{};  ///< lung frame (LPS)
  double radius_mm = 0;               ///< (0, 50]
  bool from_label = false;            ///< segmented: the ball of its volume at its centroid (sim/motion/lesion.h)
};

/// The whole asset.
struct BakedAsset {
  std::uint32_t bands = 4;               ///< L; the SH has L^2 coefficients per vertex
  double p0 = 10.0;                      ///< force model p = p0 + gamma g.(x - c)
  double gamma_per_mm = 0.025;
  double decay_length_mm = 10.0;         ///< tether length l in the stiffness
  MotionModel motion_model = MotionModel::paper;  ///< how T was baked (sim/motion/motion_model.h)
  std::vector<float> positions;          ///< 3 per vertex, mm, lung frame (LPS)
  std::vector<float> normals;            ///< 3 per vertex, outward unit
  /// 3 per vertex, unit: the direction of the vertex's displacement, p' = p + D e (the normal in the paper's
  /// model). The first-order swept volume of a displacement D is sum_I A_I D_I (e_I . n_I).
  std::vector<float> directions;
  std::vector<float> areas;              ///< 1 per vertex, mm^2 (a third of its triangles)
  std::vector<std::uint8_t> lung_of_vertex;  ///< index into lungs
  std::vector<float> sh_coeffs;          ///< L^2 per vertex: T^I_lm
  std::vector<float> linear_coeffs;      ///< 4 per vertex: tau0, tau_x, tau_y, tau_z (exact linear basis)
  /// Sliding model (empty for the paper's): 12 per vertex, the part of the vector linear basis off the direction
  /// e_I, r = tau_vec - e (e . tau_vec), as three rows x, y, z of (r0, r_x, r_y, r_z), mm per unit pressure.
  /// The vertex moves by D e + r . w, w the linear weights of the orientation (sim/force/force_sh.h,
  /// linear_weights), so that the linear pressure's full vector displacement is exact and only its part along
  /// e carries the SH (docs/design.md, "Vector displacement").
  std::vector<float> off_axis;
  bool has_off_axis() const { return !off_axis.empty(); }
  /// 3 per vertex, unit: u_I, where the bake's sphere map put the vertex, the point at which the SH of a force is
  /// evaluated for it (the force SH is the area-weighted fit of the pressure at the u_I). Lets a force pattern that
  /// is not linear in position be projected at load and per posture (sim/force/dependent_collapse.h). Empty in
  /// assets of format version 1 and 2.
  std::vector<float> sphere_dirs;
  bool has_sphere_dirs() const { return !sphere_dirs.empty(); }
  std::vector<std::uint32_t> triangles;  ///< 3 per triangle, global vertex indices
  std::vector<BakedLung> lungs;
  std::vector<BakedLesion> lesions;  ///< none unless baked with --lesion (format version 4 on)

  /// Optional (empty when not baked): explicit rows of T truncated below
  /// transfer_epsilon * T_II, in compressed sparse row form over global vertex indices, mm per unit force,
  /// for the paper's CPU eq. (1) baseline (sim/deform/deform_eq1.h). A row only holds its own lung's vertices.
  std::vector<std::uint32_t> transfer_row_ptr;  ///< vertex_count + 1 offsets into transfer_cols/vals
  std::vector<std::uint32_t> transfer_cols;
  std::vector<float> transfer_vals;
  double transfer_epsilon = 0;
  bool has_transfer_rows() const { return !transfer_row_ptr.empty(); }

  std::uint32_t coefficients() const { return bands * bands; }
  std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(lung_of_vertex.size()); }
};

}  // namespace lungar::sim
