/// @file calibrate_command.h
/// @brief `lungar calibrate`: model fiducials + stylus touches -> the [registration] section and its error.
#pragma once

#include <string>
#include <vector>

#include "platform/registration/fiducial_registration.h"

namespace lungar::platform {

struct CalibrateOptions {
  std::string model_csv;
  std::string stylus_csv;   ///< touched points in the patient-tracker frame, or
  std::string stylus_log;   ///< a .trk log of the stylus dwelling on each fiducial
  std::string config_path;  ///< for the report layout when the log's header has none
  std::string out_path;
};

/// Stylus touches from a tracker log: each stylus sample is taken into the patient tracker's frame (by the newest
/// patient pose, when the log has one), then dwells become fiducials. An error names the file.
Result<std::vector<Eigen::Vector3d>> stylus_points_from_log(const std::string& log_path,
                                                            const std::string& config_path);

/// The whole command; prints the registration and its error, returns the exit code.
int run_calibrate(const CalibrateOptions& o);

}  // namespace lungar::platform
