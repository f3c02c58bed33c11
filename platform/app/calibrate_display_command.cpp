/// @file calibrate_display_command.cpp
/// @brief Fits each eye, reports and writes (calibrate_display_command.h); the CSV read here, the interactive
///        gathering in spaam_command.cpp.
#include "platform/app/calibrate_display_command.h"

#include <cstdio>
#include <filesystem>

#include "platform/app/calibrate_command.h"
#include "platform/app/spaam_command.h"

namespace lungar::platform {

void calibrate_display_say(const std::string& message) {
  std::fprintf(stderr, "lungar calibrate-display: %s\n", message.c_str());
}

std::string saved_alignments_path(const CalibrateDisplayOptions& o) {
  if (!o.save_alignments.empty()) return o.save_alignments;
  std::filesystem::path p(o.out_path);
  if (p.extension() == ".toml") p.replace_extension();
  return p.string() + "-alignments.csv";
}

int fit_and_report(const std::array<std::vector<Alignment>, 2>& alignments, const CalibrateDisplayOptions& o,
                   const std::string& source) {
  std::array<EyeCalibration, 2> eyes;
  for (int e = 0; e < 2; ++e) {
    auto fitted = calibrate_eye(alignments[e]);
    if (!fitted)
      return calibrate_display_say(source + ": " + (e == 0 ? "left" : "right") + " eye: " + fitted.error()), 2;
    eyes[e] = *fitted;
  }
  if (Status s = write_display_calibration_toml(o.out_path, eyes); !s) return calibrate_display_say(s.error()), 1;
  if (!o.report_json.empty()) {
    if (Status s = write_display_calibration_json(o.report_json, eyes); !s) return calibrate_display_say(s.error()), 1;
  }
  for (int e = 0; e < 2; ++e) {
    const EyeCalibration& c = eyes[e];
    std::printf(
        "%s eye from %d alignments: reprojection RMS %.2f px (worst %.2f px); centre [%.1f, %.1f, %.1f] mm "
        "in the head sensor's frame; focal %.1f / %.1f px, principal point (%.1f, %.1f) px\n",
        e == 0 ? "left" : "right", c.alignments, c.rms_px, c.max_px, c.centre_mm.x(), c.centre_mm.y(), c.centre_mm.z(),
        c.intrinsics(0, 0), c.intrinsics(1, 1), c.intrinsics(0, 2), c.intrinsics(1, 2));
  }
  std::printf("written to %s; the runtime reads it: lungar %s\n", o.out_path.c_str(),
              config_flags(o.config_paths, o.out_path).c_str());
  return 0;
}

int run_calibrate_display(const CalibrateDisplayOptions& o) {
  if (o.alignments_csv.empty()) return run_spaam_calibration(o);
  if (!o.save_alignments.empty() || o.stylus_tip_mm || o.fiducial_mm || o.grid != kSpaamGridSide) {
    return calibrate_display_say(
               "--save-alignments, --stylus-tip-mm, --fiducial-mm and --grid apply to the interactive way "
               "(without --alignments)"),
           2;
  }
  auto read = read_alignments_csv(o.alignments_csv);
  if (!read) return calibrate_display_say(read.error()), 2;
  return fit_and_report(*read, o, o.alignments_csv);
}

}  // namespace lungar::platform
