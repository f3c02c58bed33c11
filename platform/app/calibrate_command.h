/// @file calibrate_command.h
/// @brief `lungar calibrate`: model fiducials + stylus touches -> the [registration] section and its error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "platform/registration/fiducial_registration.h"
#include "platform/registration/landmark_matching.h"

namespace lungar::platform {

struct CalibrateOptions {
  std::string model_csv;
  std::string stylus_csv;   ///< touched points in the patient-tracker frame, or
  std::string stylus_log;   ///< a .trk log of the stylus dwelling on each fiducial
  /// --config, repeatable (later over earlier): the report layout when the log's header has none, the stylus tip
  std::vector<std::string> config_paths;
  std::string out_path;
  std::optional<Eigen::Vector3d> stylus_tip_mm;  ///< the tip in the stylus frame; unset: [trackers.stylus]'s
};

/// `lungar calibrate pivot`: a log of the stylus pivoting about its tip -> [trackers.stylus] tip_offset_mm.
struct PivotOptions {
  std::string stylus_log;
  std::vector<std::string> config_paths;
  std::string out_path;
};

/// A log's stylus poses in the patient tracker's frame (by the newest patient pose, when the log has one), their
/// times (s from the first record), and the stylus's tip offset: the config's when one is given, else the log
/// header's layout's.
struct StylusLog {
  std::vector<double> t_s;
  std::vector<Eigen::Isometry3d> poses;
  Eigen::Vector3d tip_offset_mm = Eigen::Vector3d::Zero();
};
Result<StylusLog> stylus_poses_from_log(const std::string& log_path, const std::vector<std::string>& config_paths);

/// Stylus touches from a tracker log: each stylus pose's tip (`tip_mm`, else the layout's tip_offset_mm) in the
/// patient tracker's frame, then dwells become fiducials. An error names the file; a tip offset that is missing
/// (none given and the layout's all zero: no pivot calibration) is one, saying how to find it.
Result<std::vector<Eigen::Vector3d>> stylus_points_from_log(const std::string& log_path,
                                                            const std::vector<std::string>& config_paths,
                                                            const std::optional<Eigen::Vector3d>& tip_mm = {});

/// The same touches as dwells (where, when, how long), for landmark_matching.h.
Result<std::vector<Dwell>> stylus_dwells_from_log(const std::string& log_path,
                                                  const std::vector<std::string>& config_paths,
                                                  const std::optional<Eigen::Vector3d>& tip_mm = {});

/// The --config options that read a step's output after the settings it was given: "--config A --config OUT"
/// (each path quoted for the shell where it needs it), for the line that says how to go on.
std::string config_flags(const std::vector<std::string>& given, const std::string& out_path);

/// The pivot command; prints the tip and its error, returns the exit code.
int run_pivot(const PivotOptions& o);

/// The whole command; prints the registration and its error, returns the exit code.
int run_calibrate(const CalibrateOptions& o);

}  // namespace lungar::platform
