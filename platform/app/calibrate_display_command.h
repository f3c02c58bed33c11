/// @file calibrate_display_command.h
/// @brief `lungar calibrate-display`: SPAAM alignments -> each eye's 3 x 4 projection, [hmd.display_calibration].
#pragma once

#include <string>

namespace lungar::platform {

struct CalibrateDisplayOptions {
  std::string alignments_csv;  ///< eye,x_mm,y_mm,z_mm,u_px,v_px
  std::string out_path;        ///< the [hmd.display_calibration] TOML
  std::string report_json;     ///< optional: each eye's figures
};

/// Fits both eyes, prints each eye's reprojection RMS and centre, writes the TOML (and the report); nothing is
/// written when an eye is refused. Returns the exit code.
int run_calibrate_display(const CalibrateDisplayOptions& o);

}  // namespace lungar::platform
