/// @file doctor_check.cpp
/// @brief The doctor's line format and the environment its checks read.
#include "platform/doctor/doctor_check.h"

#include <cstdio>
#include <cstdlib>

namespace lungar::platform::doctor {

namespace {

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? std::string(v) : fallback;
}

}  // namespace

std::string format_check(const Check& c) {
  static const char* const kWords[] = {"ok", "warn", "FAIL"};
  char head[32];
  std::snprintf(head, sizeof head, "%-5s %-8s ", kWords[static_cast<int>(c.verdict)], c.name.c_str());
  std::string line = head + c.detail;
  if (!c.fix.empty()) line += (c.verdict == Verdict::Fail ? " -- fix: " : " -- ") + c.fix;
  return line;
}

DoctorEnv DoctorEnv::from_environment() {
  DoctorEnv e;
  e.xdg = config::XdgDirs::from_environment();
  e.display = env_or("DISPLAY", "");
  e.xr_runtime_json = env_or("XR_RUNTIME_JSON", "");
  const std::string dirs = env_or("XDG_CONFIG_DIRS", "/etc/xdg");
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t colon = std::min(dirs.find(':', start), dirs.size());
    if (colon > start && dirs[start] == '/') e.xdg_config_dirs.push_back(dirs.substr(start, colon - start));
    start = colon + 1;
  }
  return e;
}

}  // namespace lungar::platform::doctor
