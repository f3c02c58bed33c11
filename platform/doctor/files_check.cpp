/// @file files_check.cpp
/// @brief The file checks: the settings file parses, the asset loads (or the demo's cache can be made), and the
/// disk holding snapshots, stats and recordings has room.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "platform/app/demo_asset.h"
#include "platform/doctor/checks.h"
#include "sim/asset/asset_io.h"

namespace lungar::platform::doctor {

namespace {

namespace fs = std::filesystem;

/// `path` or its nearest ancestor that exists: where a folder would be made, and whose disk it would be on.
fs::path existing_ancestor(fs::path path) {
  std::error_code ec;
  while (!path.empty() && !fs::exists(path, ec) && path.has_parent_path() && path != path.parent_path()) {
    path = path.parent_path();
  }
  return path;
}

std::string gib(std::uintmax_t bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f GiB", static_cast<double>(bytes) / (1u << 30));
  return b;
}

std::string asset_summary(const sim::BakedAsset& a) {
  return std::to_string(a.vertex_count()) + " nodes, " + std::to_string(a.lungs.size()) + " lungs, " +
         std::to_string(a.coefficients()) + " SH coefficients";
}

}  // namespace

Check check_config(const config::ConfigChoice& choice, const Result<Settings>& loaded) {
  const std::string where = choice.files();
  std::error_code ec;
  const bool one_missing =
      std::any_of(choice.paths.begin(), choice.paths.end(), [&](const std::string& p) { return !fs::exists(p, ec); });
  if (!loaded && one_missing) {
    return failed("config", loaded.error(),
                  "give each --config an existing file, or none to use " +
                      std::string("~/.config/lungar/lungar.toml or /etc/lungar/lungar.toml"));
  }
  if (!loaded) {
    return failed("config", loaded.error(),
                  "correct that key (every key, its unit and range: /usr/share/lungar/default.toml or "
                  "config/default.toml), or move " +
                      where + " away to run on the defaults");
  }
  return passed("config", where + " (" + choice.reason + ")");
}

Check check_asset(const Settings& s, const DoctorEnv& env, bool procedural) {
  if (!s.sim.asset.empty()) {
    auto asset = sim::load_asset(s.sim.asset);
    if (!asset) {
      return failed("asset", "sim.asset: " + asset.error(),
                    "bake it again (lungar-bake --mesh LUNG.stl --units mm --out " + s.sim.asset +
                        "), or empty sim.asset to use the demo lungs");
    }
    return passed("asset", s.sim.asset + ": " + asset_summary(*asset));
  }
  DemoAssetOptions demo;
  demo.procedural = procedural;
  demo.cache_dir = config::cache_dir(env.xdg);
  const std::string cached = demo_cache_path(demo);
  std::error_code ec;
  if (fs::exists(cached, ec)) {
    auto asset = sim::load_asset(cached);
    if (!asset) {
      return warned("asset", "the cached demo asset is unusable (" + asset.error() + "); the next run bakes it again",
                    "nothing to do, or rm " + cached);
    }
    return passed("asset", "demo lungs cached at " + cached + ": " + asset_summary(*asset));
  }
  const fs::path parent = existing_ancestor(demo.cache_dir);
  if (::access(parent.c_str(), W_OK) != 0) {
    return warned(
        "asset",
        "the demo lungs are not baked yet and " + parent.string() + " is not writable: every run will bake them again",
        "make " + demo.cache_dir + " writable for this user, or set XDG_CACHE_HOME");
  }
  return passed("asset", "demo lungs not baked yet: the first run bakes them once into " + demo.cache_dir);
}

Check check_disk(const DoctorEnv& env) {
  const std::string dir = config::state_dir(env.xdg);
  const fs::path on = existing_ancestor(dir);
  std::error_code ec;
  const fs::space_info space = fs::space(on, ec);
  if (ec)
    return failed("disk", dir + ": cannot read the free space of " + on.string() + ": " + ec.message(),
                  "set XDG_STATE_HOME to a folder on a mounted, writable disk");
  if (::access(on.c_str(), W_OK) != 0) {
    return failed("disk", dir + ": " + on.string() + " is not writable by this user",
                  "make it writable (sudo chown -R $USER " + on.string() + ") or set XDG_STATE_HOME");
  }
  const std::string detail = gib(space.available) + " free for snapshots, stats and recordings in " + dir;
  if (space.available < env.min_free_bytes) {
    return failed("disk", detail + "; expected at least " + gib(env.min_free_bytes),
                  "free space on that disk, or set XDG_STATE_HOME to a folder on a larger one");
  }
  return passed("disk", detail);
}

}  // namespace lungar::platform::doctor
