/// @file display_calibration.h
/// @brief Each eye's projection of an optical see-through HMD from SPAAM alignments (Tuceryan and Navab, 2000):
///        the user lines an on-screen crosshair up with a tracked point, many times per eye; each alignment pairs
///        the point in the head tracker's sensor frame (mm) with the crosshair's pixel in that eye's viewport
///        (origin top-left). The normalised direct linear transform (Hartley and Zisserman, ch. 4.4 and 7.1) fits
///        the eye's 3 x 4 projection P, u ~ P X; its RQ decomposition gives the intrinsics and the eye's centre.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "config/base/result.h"

namespace lungar::platform {

/// Fewer alignments per eye cannot fix P's 11 degrees of freedom with any redundancy.
inline constexpr int kMinAlignmentsPerEye = 6;
/// The points' smallest spread over their largest (singular values of the centred points): below it they lie
/// near a plane (one depth, say) and the DLT cannot separate the focal length from the distance.
inline constexpr double kMinAlignmentSpreadRatio = 0.02;

struct Alignment {
  Eigen::Vector3d point_mm;  ///< in the head tracker's sensor frame
  Eigen::Vector2d pixel;     ///< in the eye's viewport, origin top-left
};

/// One eye's calibration.
struct EyeCalibration {
  Eigen::Matrix<double, 3, 4> projection;  ///< sensor mm -> homogeneous pixels; scaled so that K(2,2) = 1
  Eigen::Matrix3d intrinsics;              ///< K: focal lengths, skew, principal point (pixels)
  Eigen::Matrix3d rotation;                ///< R: sensor -> eye camera (x right, y down, z forward)
  Eigen::Vector3d centre_mm;               ///< the eye's centre in the sensor frame
  double rms_px = 0;                       ///< reprojection error of the alignments
  double max_px = 0;
  int alignments = 0;
};

/// Reads `eye,x_mm,y_mm,z_mm,u_px,v_px` (one alignment a line, eye left or right, after an optional header naming
/// those columns: csv_header.h); the error names the file and the line.
Result<std::array<std::vector<Alignment>, 2>> read_alignments_csv(const std::string& path);

/// Writes what read_alignments_csv() reads (the left eye's, then the right's; 0.001 mm and 0.01 px), whole or not
/// at all: an interactive session's alignments, kept so that a fit can be redone or the alignments inspected.
Status write_alignments_csv(const std::string& path, const std::array<std::vector<Alignment>, 2>& eyes);

/// The DLT fit of one eye; refused (one line) with fewer than kMinAlignmentsPerEye alignments, or points near a
/// plane or a line.
Result<EyeCalibration> calibrate_eye(const std::vector<Alignment>& alignments);

/// P's intrinsics, rotation and centre (P scaled to K(2,2) = 1 and signed so that points in front have positive
/// depth first); an error when P's left 3 x 3 is singular or mirrored.
Result<EyeCalibration> decompose_projection(Eigen::Matrix<double, 3, 4> p);

/// `u ~ P X`: the pixel a sensor-frame point projects to.
Eigen::Vector2d project(const Eigen::Matrix<double, 3, 4>& p, const Eigen::Vector3d& x);

/// Writes [hmd.display_calibration] left_projection_3x4 and right_projection_3x4 (row-major), whole or not at all.
Status write_display_calibration_toml(const std::string& path, const std::array<EyeCalibration, 2>& eyes);

/// The report: per eye its alignments, reprojection RMS and worst (px), centre (mm), focal lengths and principal
/// point (px); whole or not at all.
Status write_display_calibration_json(const std::string& path, const std::array<EyeCalibration, 2>& eyes);

}  // namespace lungar::platform
