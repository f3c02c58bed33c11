/// @file motion_model.h
/// @brief Which way the lung surface moves when it breathes: the paper's model (every vertex along its normal)
///        or the sliding model (driven by the diaphragm, sliding along the chest wall, held at the mediastinum).
///
/// Both are Green's functions of the same stiffness, K = L_E + diag(s_I kappa_I) (docs/design.md, "Transfer
/// matrix"), baked once. They differ in their boundary conditions (docs/design.md, "Vector displacement"):
/// - paper: a scalar displacement along n_I under a pressure force along n_J, s_I = 1 everywhere;
/// - sliding: a vector displacement u = K^-1 F per component, under F_J = A_J p(J) b_J with a drive direction
///   b_J per face (diaphragmatic: caudal; costal: a push along the normal, the ribs' pump- and bucket-handle
///   motion, and a caudal slide that fades towards the top; apical: the push alone; mediastinal: none) and a
///   tether factor s per face (diaphragmatic, costal and apical: weak, so the faces follow the diaphragm and slide;
///   mediastinal: strong, held at the hilum). Each vertex then moves along one baked direction e_I, the principal
///   direction of its displacement over every orientation, so that the run time is the paper's,
///   D = sum f_lm T^I_lm, p' = p + D e_I, plus an off-axis part exact for the linear pressure (sim/asset/baked_asset.h, off_axis).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "config/base/enum_names.h"
#include "sim/motion/surface_regions.h"

namespace lungar::sim {

enum class MotionModel : std::uint8_t { paper, sliding };
inline constexpr EnumNames<MotionModel, 2> kMotionModelNames{
    {{{MotionModel::paper, "paper"}, {MotionModel::sliding, "sliding"}}}};

/// The sliding model's boundary conditions, per face: the tether factor s on the paper's kappa_I, and the
/// drive's weight (the diaphragm's along -z, the costal and apical faces' along their normals, the costal face's
/// caudal slide). The defaults give about three quarters of a quiet breath to the diaphragm, as in awake supine
/// adults (docs/design.md, "Vector displacement").
struct SlidingFaces {
  std::array<double, kSurfaceRegionCount> tether{};  ///< indexed by SurfaceRegion
  std::array<double, kSurfaceRegionCount> drive{};
  /// The diaphragm's drive grows from front to back: 1 + dorsal_gain * (y - y_mid) / depth, y the vertex's depth
  /// (+y posterior) in the lung's extent. Its dorsal (crural) part has the longest fibres and moves most, upright
  /// as well as supine (MRI of the diaphragm: Takazakura et al., Respir Physiol Neurobiol 2004); gravity adds to
  /// it through the pressure.
  double dorsal_gain = 2.0;
  /// The costal face's caudal drive, on the diaphragm's scale: the lung slides down along the chest wall as its base
  /// descends (4-D CT's lower-lobe landmarks move nearly as the diaphragm does, the upper ones a little). It is
  /// strongest at the bottom of the lung and fades to none at the top as sqrt(1 - h), h the height in the lung's
  /// extent; like the diaphragm's, it grows towards the back, by 1 + slide_dorsal_gain * (y - y_mid) / depth.
  /// Tangential, it moves tissue more than it changes volume: with it the mean displacement inside the lungs
  /// reaches 4-D CT's (4.1 mm at 500 mL, where the diaphragm alone gave 3.0) and the base rises on an expiration as
  /// far as it does in CT (docs/design.md, "Vector displacement").
  double costal_slide = 0.5;
  double slide_dorsal_gain = 1.0;
};
SlidingFaces default_sliding_faces();

/// Per vertex: the tether factor s_I and the drive direction b_J (zero where a face is not driven).
struct MotionBoundary {
  std::vector<double> tether_scale;
  Eigen::MatrixXd drive;  ///< N x 3
};
MotionBoundary sliding_boundary(const std::vector<SurfaceRegion>& regions, const TriMesh& mesh,
                                const std::vector<Eigen::Vector3d>& normals, const SlidingFaces& faces);

/// e_I from one vertex's displacement under the four linear pressures (tau0 for p = 1, tau_k for p = (x - c)_k):
/// the principal direction of p0 tau0 and gamma * radius * tau_k, signed so that e . tau0 >= 0; `fallback` (the
/// normal) where the vertex does not move.
Eigen::Vector3d principal_direction(const Eigen::Vector3d& tau0, const Eigen::Matrix3d& tau_grad, double p0,
                                    double gamma_radius, const Eigen::Vector3d& fallback);

}  // namespace lungar::sim
