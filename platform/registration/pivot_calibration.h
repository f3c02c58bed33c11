/// @file pivot_calibration.h
/// @brief Where a tracked stylus's tip is, from the stylus pivoting about it: the tip rests in a dimple while the
///        handle sweeps a cone, so every pose (R_i, p_i) maps one unknown tip offset t (stylus frame) to one unknown
///        fixed point q: R_i t + p_i = q. Stacked, [R_i  -I] [t; q] = -p_i is linear least squares in six unknowns
///        (the standard pivot calibration, as PLUS's and 3D Slicer's). Its residual |R_i t + p_i - q| says how well
///        the tip stayed put.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "config/base/result.h"

namespace lungar::platform {

/// Fewer poses, or a cone narrower than this, leave the tip undetermined along the stylus's axis.
inline constexpr int kMinPivotPoses = 8;
inline constexpr double kMinPivotSpreadDeg = 15.0;
/// Poses turned about one axis only (a hinge, not a cone) fit every tip along that axis: the stylus direction that
/// turned least must have moved this much (RMS about its mean, degrees). A cone swept all round, 15 degrees across,
/// moves it about 5; a hinge with a tracker's orientation noise, a few tenths.
inline constexpr double kMinPivotLeastTurnDeg = 1.5;

struct PivotFit {
  Eigen::Vector3d tip_mm = Eigen::Vector3d::Zero();    ///< t: the tip in the stylus sensor's frame
  Eigen::Vector3d pivot_mm = Eigen::Vector3d::Zero();  ///< q: the fixed point, in the poses' frame
  double rms_mm = 0;                                   ///< RMS of |R_i t + p_i - q|
  double max_mm = 0;
  double spread_deg = 0;      ///< the largest angle between any pose's orientation and the first's
  double least_turn_deg = 0;  ///< how far the stylus direction that turned least moved (RMS, degrees)
  int poses = 0;
};

/// The least-squares pivot; an error (one line) with too few poses, too little rotation or rotation about one axis
/// only, any of which leaves the tip undetermined.
Result<PivotFit> fit_pivot(const std::vector<Eigen::Isometry3d>& stylus_poses);

/// Writes "[trackers.stylus] tip_offset_mm = [...]" with a comment giving the fit's error, whole or not at all.
Status write_tip_offset_toml(const std::string& path, const PivotFit& fit);

}  // namespace lungar::platform
