/// @file doctor_check.h
/// @brief `lungar doctor`: what one check found (pass, a warning that does not fail the set-up, or a failure), the
/// fix a lab engineer can type, and the folders and variables the checks read (DoctorEnv), so tests can point them
/// at temporary folders.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/config_paths.h"

namespace lungar::platform::doctor {

enum class Verdict { Pass, Warn, Fail };

struct Check {
  std::string name;  ///< "gles", "output", "tracker", ...
  Verdict verdict = Verdict::Pass;
  std::string detail;  ///< what was found
  std::string fix;     ///< what to do (a command where there is one); empty on a pass
};

inline Check passed(std::string name, std::string detail) {
  return {std::move(name), Verdict::Pass, std::move(detail), ""};
}
inline Check warned(std::string name, std::string detail, std::string fix) {
  return {std::move(name), Verdict::Warn, std::move(detail), std::move(fix)};
}
inline Check failed(std::string name, std::string detail, std::string fix) {
  return {std::move(name), Verdict::Fail, std::move(detail), std::move(fix)};
}

/// One line: "ok    tracker  /dev/hidraw0 ...", "FAIL  tracker  ... -- fix: COMMAND".
std::string format_check(const Check& c);

/// What the checks look at besides the settings.
struct DoctorEnv {
  config::XdgDirs xdg;
  std::string display;                       ///< $DISPLAY
  std::string xr_runtime_json;               ///< $XR_RUNTIME_JSON
  std::vector<std::string> xdg_config_dirs;  ///< $XDG_CONFIG_DIRS, default /etc/xdg
  std::string sysconf_dir = "/etc";          ///< the OpenXR loader's last place to look
  std::vector<std::string> udev_rule_dirs = {"/etc/udev/rules.d", "/run/udev/rules.d", "/usr/local/lib/udev/rules.d",
                                             "/usr/lib/udev/rules.d", "/lib/udev/rules.d"};
  std::uint64_t min_free_bytes = 1ull << 30;  ///< below this, recordings may not fit: a failure

  static DoctorEnv from_environment();
};

}  // namespace lungar::platform::doctor
