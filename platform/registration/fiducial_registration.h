/// @file fiducial_registration.h
/// @brief Registration of the lung model onto the patient simulator from paired fiducials (Umeyama's method).
///
/// The trainer touches known landmarks of the simulator with a tracked stylus; the same landmarks are known in
/// the lung model's frame. The rigid transform model -> patient tracker that best maps one set onto the other
/// (least squares, no scale) is the registration; its RMS residual is the fiducial registration error (FRE).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "config/base/result.h"

namespace lungar::platform {

struct Registration {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< model -> patient tracker
  Eigen::Vector3d translation_mm = Eigen::Vector3d::Zero();
  double fre_rms_mm = 0;      ///< RMS fiducial registration error
  double fre_max_mm = 0;      ///< the worst fiducial's error
  int fiducials = 0;

  Eigen::Vector3d apply(const Eigen::Vector3d& model_point) const { return rotation * model_point + translation_mm; }
};

/// Rigid least-squares fit of `model` onto `tracked` (row k pairs with row k). Needs at least 3 points that are not
/// collinear; the error says why otherwise.
Result<Registration> register_fiducials(const std::vector<Eigen::Vector3d>& model,
                                        const std::vector<Eigen::Vector3d>& tracked);

/// One sample of the stylus tip (patient frame); landmark_matching.h finds the touches in a track of them.
struct StylusSample {
  double t_s = 0;
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
};

/// Reads fiducial points, one "x, y, z" (mm) a line, '#' comments allowed, after an optional header
/// "x_mm,y_mm,z_mm" (csv_header.h). An error names file, line and field.
Result<std::vector<Eigen::Vector3d>> read_points_csv(const std::string& path);

/// Writes the registration as the [registration] section of a lungar config, whole or not at all.
Status write_registration_toml(const std::string& path, const Registration& r);

}  // namespace lungar::platform
