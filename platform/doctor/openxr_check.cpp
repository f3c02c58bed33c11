/// @file openxr_check.cpp
/// @brief The OpenXR check: the active runtime's manifest, found where the OpenXR loader looks on Linux
/// (XR_RUNTIME_JSON; else openxr/1/active_runtime.<arch>.json, then active_runtime.json, in $XDG_CONFIG_HOME,
/// each of $XDG_CONFIG_DIRS, then /etc), and the runtime library it names. OpenXR itself is not loaded.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "platform/doctor/checks.h"

namespace lungar::platform::doctor {

namespace {

namespace fs = std::filesystem;

/// The loader's architecture name for active_runtime.<arch>.json.
constexpr const char* kArch =
#if defined(__x86_64__)
    "x86_64";
#elif defined(__aarch64__)
    "aarch64";
#elif defined(__arm__)
    "armv7a-vfp";
#elif defined(__i386__)
    "i686";
#else
    "unknown";
#endif

const char* const kInstallFix =
    "install the HMD's OpenXR runtime (Monado, SteamVR, the vendor's) and make it active: mkdir -p "
    "~/.config/openxr/1 && ln -sf RUNTIME_MANIFEST.json ~/.config/openxr/1/active_runtime.json (or set "
    "XR_RUNTIME_JSON to the manifest)";

/// The first active-runtime manifest in the loader's order; "" when there is none.
std::string find_manifest(const DoctorEnv& env, std::vector<std::string>& looked) {
  if (!env.xr_runtime_json.empty()) {
    looked.push_back(env.xr_runtime_json);
    return env.xr_runtime_json;  // the loader looks nowhere else, even when it is missing
  }
  std::vector<std::string> dirs;
  const std::string home_config =
      !env.xdg.config_home.empty() ? env.xdg.config_home : (env.xdg.home.empty() ? "" : env.xdg.home + "/.config");
  if (!home_config.empty()) dirs.push_back(home_config);
  dirs.insert(dirs.end(), env.xdg_config_dirs.begin(), env.xdg_config_dirs.end());
  dirs.push_back(env.sysconf_dir);
  for (const auto& dir : dirs) {
    for (const std::string& name :
         {std::string("active_runtime.") + kArch + ".json", std::string("active_runtime.json")}) {
      const std::string path = dir + "/openxr/1/" + name;
      looked.push_back(path);
      std::error_code ec;
      if (fs::exists(path, ec)) return path;
    }
  }
  return "";
}

/// The library a manifest names: absolute, relative to the manifest's folder, or a bare name for the linker.
std::string resolve_library(const std::string& manifest, const std::string& library) {
  if (library.find('/') == std::string::npos || fs::path(library).is_absolute()) return library;
  return (fs::path(manifest).parent_path() / library).lexically_normal().string();
}

}  // namespace

Check check_openxr_runtime(const DoctorEnv& env) {
  std::vector<std::string> looked;
  const std::string manifest = find_manifest(env, looked);
  std::error_code ec;
  if (manifest.empty() || !fs::exists(manifest, ec)) {
    std::string where;
    for (const auto& p : looked) where += (where.empty() ? "" : ", ") + p;
    return failed("openxr", "no active OpenXR runtime (looked for " + where + ")", kInstallFix);
  }
  nlohmann::json j;
  try {
    std::ifstream in(manifest);
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    return failed("openxr", manifest + ": expected a JSON runtime manifest, got a parse error (" + e.what() + ")",
                  kInstallFix);
  }
  const auto runtime = j.find("runtime");
  if (runtime == j.end() || !runtime->is_object() || !runtime->contains("library_path") ||
      !(*runtime)["library_path"].is_string()) {
    return failed("openxr", manifest + ": runtime.library_path: expected a string, got none", kInstallFix);
  }
  const std::string library = resolve_library(manifest, (*runtime)["library_path"].get<std::string>());
  const std::string name = runtime->value("name", fs::path(library).filename().string());
  if (library.find('/') != std::string::npos && !fs::exists(library, ec)) {
    return failed("openxr", manifest + ": runtime.library_path: " + library + " does not exist",
                  "reinstall the runtime " + name + ", or make another one active (" + kInstallFix + ")");
  }
  return passed("openxr", "runtime " + name + " (" + library + ") from " + manifest);
}

}  // namespace lungar::platform::doctor
