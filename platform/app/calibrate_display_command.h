/// @file calibrate_display_command.h
/// @brief `lungar calibrate-display`: SPAAM alignments -> each eye's 3 x 4 projection, [hmd.display_calibration].
///        The alignments come from a CSV (offline), or from the user lining crosshairs up on the HMD
///        (interactive, spaam_command.h); both go through fit_and_report().
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "platform/registration/spaam_session.h"
#include "platform/registration/display_calibration.h"

namespace lungar::platform {

struct CalibrateDisplayOptions {
  std::string alignments_csv;  ///< eye,x_mm,y_mm,z_mm,u_px,v_px; empty: gather them interactively
  std::string out_path;        ///< the [hmd.display_calibration] TOML
  std::string report_json;     ///< optional: each eye's figures
  // The interactive way only:
  std::string save_alignments;  ///< where the gathered alignments go; empty: beside out_path (saved_alignments_path)
  /// the settings with the tracker, the display and the HMD (repeatable, later over earlier); none: the chosen one
  std::vector<std::string> config_paths;
  std::optional<Eigen::Vector3d> stylus_tip_mm;  ///< the tip in the stylus frame; unset: [trackers.stylus]'s
  std::optional<Eigen::Vector3d> fiducial_mm;    ///< align with this point on the patient tracker, not the stylus
  int grid = kSpaamGridSide;                     ///< grid x grid crosshair positions an eye
};

/// Where the interactive way keeps its alignments: --save-alignments, else `<out without .toml>-alignments.csv`.
std::string saved_alignments_path(const CalibrateDisplayOptions& o);

/// One line on stderr as the command says it: "lungar calibrate-display: MESSAGE".
void calibrate_display_say(const std::string& message);

/// Fits both eyes, prints each eye's reprojection RMS and centre, writes the TOML (and the report); nothing is
/// written when an eye is refused (the error names `source`, where the alignments came from). The exit code.
int fit_and_report(const std::array<std::vector<Alignment>, 2>& alignments, const CalibrateDisplayOptions& o,
                   const std::string& source);

/// The whole command, either way. Returns the exit code.
int run_calibrate_display(const CalibrateDisplayOptions& o);

}  // namespace lungar::platform
