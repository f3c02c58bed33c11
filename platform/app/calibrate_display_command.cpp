/// @file calibrate_display_command.cpp
/// @brief Reads the alignments, fits each eye, reports and writes (calibrate_display_command.h).
#include "platform/app/calibrate_display_command.h"

#include <cstdio>

#include "platform/registration/display_calibration.h"

namespace lungar::platform {

int run_calibrate_display(const CalibrateDisplayOptions& o) {
  auto say = [](const std::string& m) { std::fprintf(stderr, "lungar calibrate-display: %s\n", m.c_str()); };
  auto read = read_alignments_csv(o.alignments_csv);
  if (!read) return say(read.error()), 2;
  std::array<EyeCalibration, 2> eyes;
  for (int e = 0; e < 2; ++e) {
    auto fitted = calibrate_eye((*read)[e]);
    if (!fitted) return say(o.alignments_csv + ": " + (e == 0 ? "left" : "right") + " eye: " + fitted.error()), 2;
    eyes[e] = *fitted;
  }
  if (Status s = write_display_calibration_toml(o.out_path, eyes); !s) return say(s.error()), 1;
  if (!o.report_json.empty()) {
    if (Status s = write_display_calibration_json(o.report_json, eyes); !s) return say(s.error()), 1;
  }
  for (int e = 0; e < 2; ++e) {
    const EyeCalibration& c = eyes[e];
    std::printf("%s eye from %d alignments: reprojection RMS %.2f px (worst %.2f px); centre [%.1f, %.1f, %.1f] mm "
                "in the head sensor's frame; focal %.1f / %.1f px, principal point (%.1f, %.1f) px\n",
                e == 0 ? "left" : "right", c.alignments, c.rms_px, c.max_px, c.centre_mm.x(), c.centre_mm.y(),
                c.centre_mm.z(), c.intrinsics(0, 0), c.intrinsics(1, 1), c.intrinsics(0, 2), c.intrinsics(1, 2));
  }
  std::printf("written to %s (include it with --config, or copy the section into your profile)\n", o.out_path.c_str());
  return 0;
}

}  // namespace lungar::platform
