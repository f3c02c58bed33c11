/// @file dependent_collapse.h
/// @brief ARDS's applied force: the dependent part of the lungs, crushed under the weight of the oedematous lung
///        above it, collapses and takes almost none of the breath's pressure. Which part is dependent follows
///        gravity, so the pattern changes with the posture and cannot be made once at load.
///
/// The model (the "sponge lung" of ARDS: a heavy, wet lung whose own weight squeezes its lowest parts shut):
/// - **How much collapses**: a share c of the pair's volume, c = S (kCollapseMid + kCollapseTilt g_y), S the
///   severity (0 to 1) and g_y gravity's posterior component (+1 supine, -1 prone). Set so that at S = 0.6 it is
///   the porcine ARDS CT's non- and poorly aerated share of lung mass: 4 + 47 = 51 % supine, 1 + 30 = 31 % prone
///   (proning recruits the dorsal lung: the heart and the abdomen no longer press on it, and more of the lung's
///   mass lies under a shorter column).
/// - **Where**: beyond the plane g . x = t across both lungs (lung frame), t chosen so that the volume beyond it is
///   c of the pair's: the dependent lung first, whichever lung that is (lying on a side, mostly the lower lung).
///   The volume beyond a plane is a surface integral, V(t) = sum A (g . x - t)+ (g . n) (the divergence theorem
///   with the field (g . x - t)+ g, zero on the plane), so no clipping is needed.
/// - **The force**: p(x; g) = (p0 + gamma g . (x - c_l)) m(g . x - t), m falling from 1 to kCollapsedPressure over
///   kCollapseRampMm across the plane (a smoothstep: CT shows a gradient of aeration, not a cut).
///
/// m makes p not linear in position, which is what the SH force is for: per posture the pattern is projected onto
/// each lung's SH (the bake's own area-weighted fit, at kSamplesPerLung points of the lung's LOD prefix and their
/// sphere points u_I, BakedAsset::sphere_dirs) and, for the part of the motion off each vertex's direction, onto
/// the linear basis (its least-squares fit a + b . (x - c_l)). The lung's swept volume is that of the displacement
/// the runtime draws, sum_I A_I n_I . (D_I e_I + r_I w), with the bake's per-lung calibration to the enclosed
/// volume, so dV stays exact; its weight in the split between the lungs carries V_ARDS(g) / V_healthy(g) as a
/// consolidation's does (sim/force/breath_share.h).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include <Eigen/Core>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"

namespace lungar::sim {

inline constexpr double kCollapseMid = 0.685;          ///< c / S with gravity across the back-front axis
inline constexpr double kCollapseTilt = 0.165;         ///< + supine, - prone: c / S = 0.85 supine, 0.52 prone
inline constexpr double kCollapsedPressure = 0.1;      ///< the collapsed region's share of the healthy pressure
inline constexpr double kCollapseRampMm = 30.0;        ///< width of the aerated-to-collapsed transition
inline constexpr std::size_t kSamplesPerLung = 4096;   ///< points of each lung's LOD prefix the pattern is fitted at

/// One lung's force under the collapse for one gravity, unnormalised (as f(g) and V(g) of force_sh.h).
struct CollapsedLungForce {
  std::vector<double> sh;            ///< L^2: the pressure pattern's SH
  std::array<double, 4> linear{};    ///< its linear fit (a, b_x, b_y, b_z): weights of tau0, tau_x, tau_y, tau_z
  double swept_mm3 = 0;              ///< the swept volume of the displacement it produces, calibrated
};

/// How well each fit carries the pattern over every vertex: sqrt(sum A (fit - p)^2 / sum A p^2).
struct CollapseFitError {
  double sh_rms_rel = 0;       ///< the force SH the shader uses
  double linear_rms_rel = 0;   ///< the best pressure linear in position (all the linear basis can carry)
};

class DependentCollapse {
 public:
  /// Fits the sample points of every lung of `asset` (which must hold sphere points: asset format 3). An error
  /// names what is missing.
  static Result<std::shared_ptr<const DependentCollapse>> build(const BakedAsset& asset, double severity);

  double severity() const { return severity_; }
  /// c: the share of the pair's volume collapsed with unit gravity g (lung frame).
  double collapsed_share(const Eigen::Vector3d& g) const;
  /// t: the plane g . x = t beyond which the lungs are collapsed.
  double threshold_mm(const Eigen::Vector3d& g) const;
  /// m(g . x - t): the share of its healthy pressure a point at x (lung frame) takes.
  static double pressure_factor(double beyond_mm);
  /// Lung `lung`'s force for gravity g (unit, lung frame); the last gravity's answer is kept, so the runtime's
  /// several calls in a frame do the work once.
  CollapsedLungForce lung_force(const BakedAsset& asset, std::size_t lung, const Eigen::Vector3d& g) const;
  /// The fits' errors against the pattern itself at every vertex of every lung, for gravity g: what the SH buys.
  CollapseFitError fit_error(const BakedAsset& asset, const Eigen::Vector3d& g) const;

 private:
  struct Samples {
    Eigen::MatrixXd positions;       ///< K x 3, lung frame
    Eigen::MatrixXd normals;         ///< K x 3
    Eigen::VectorXd weights;         ///< K: the surface area each stands for
    Eigen::MatrixXd sh_fit;          ///< L^2 x K: p at the samples -> its SH (area-weighted least squares)
    Eigen::MatrixXd linear_fit;      ///< 4 x K: p at the samples -> a, b
    Eigen::VectorXd volume_sh;       ///< L^2: swept volume per unit f_lm
    Eigen::Vector4d volume_linear;   ///< the off-axis part's swept volume per unit linear weight
    double calibration = 1;          ///< the bake's first-order -> enclosed factor
    Eigen::Vector3d centre;
  };
  double severity_ = 0;
  std::vector<Samples> lungs_;

  mutable std::mutex cache_mutex_;
  mutable Eigen::Vector3d cached_g_ = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  mutable std::vector<CollapsedLungForce> cached_;
};

}  // namespace lungar::sim
