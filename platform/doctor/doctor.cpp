/// @file doctor.cpp
/// @brief `lungar doctor`: the settings the runtime would use, every check against them, one line each.
#include "platform/doctor/doctor.h"

#include <cstdio>

#include "drivers/tracker/tracker_config.h"
#include "platform/app/settings_load.h"
#include "platform/doctor/checks.h"

namespace lungar::platform::doctor {

std::vector<Check> run_checks(const RuntimeOptions& o, const DoctorEnv& env) {
  const config::ConfigChoice choice = config::choose_config(o.config_paths, env.xdg);
  const Result<Settings> loaded = load_chosen_settings(choice);
  // A settings file that does not parse fails its check; the others still run, on the defaults.
  Settings s = loaded ? *loaded : Settings{};
  std::vector<Check> checks;
  // What the runtime would run: the options given (--tracker, --asset, --sync, ...) over the file's settings.
  if (const Status applied = apply_overrides(o, s); !applied) {
    checks.push_back(failed("options", applied.error(), "correct that option (lungar --help lists them)"));
  }
  checks.push_back(check_config(choice, loaded));
  checks.push_back(check_gles());
  checks.push_back(check_output(s, env));
  checks.push_back(check_tracker(s.trackers(), env));
  checks.push_back(check_asset(s, env, o.procedural));
  checks.push_back(check_classroom(s));
  checks.push_back(check_disk(env));
  return checks;
}

std::vector<Check> run_checks(const std::string& config_path, const DoctorEnv& env) {
  RuntimeOptions o;
  if (!config_path.empty()) o.config_paths = {config_path};
  return run_checks(o, env);
}

int run_doctor(const RuntimeOptions& o) {
  const auto checks = run_checks(o, DoctorEnv::from_environment());
  int failures = 0, warnings = 0;
  for (const auto& c : checks) {
    std::printf("%s\n", format_check(c).c_str());
    failures += c.verdict == Verdict::Fail;
    warnings += c.verdict == Verdict::Warn;
  }
  std::printf("lungar doctor: %zu checks, %d failed, %d warnings\n", checks.size(), failures, warnings);
  return failures == 0 ? 0 : 1;
}

}  // namespace lungar::platform::doctor
