/// @file demo_asset.cpp
/// @brief Bake-once cache of the procedural demo asset.
#include "platform/runtime/demo_asset.h"

#include <cstdio>
#include <filesystem>

#include "config/config_paths.h"
#include "sim/asset/asset_io.h"
#include "sim/bake/bake.h"

namespace lungar::platform {

std::string demo_asset_path(const DemoAssetOptions& o) {
  const std::string dir = o.cache_dir.empty() ? config::cache_dir(config::XdgDirs::from_environment()) : o.cache_dir;
  char name[160];
  std::snprintf(name, sizeof name, "procedural-n%u-s%llu-L%u%s-v%u-b%u.lungbake", o.nodes,
                static_cast<unsigned long long>(o.seed), o.bands, o.transfer_rows ? "-rows" : "",
                sim::kAssetVersion, sim::kBakeRevision);
  return (std::filesystem::path(dir) / name).string();
}

Result<sim::BakedAsset> load_or_bake_demo_asset(const DemoAssetOptions& o,
                                                     const std::function<void(const std::string&)>& log) {
  const std::string path = demo_asset_path(o);
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    auto loaded = sim::load_asset(path);
    if (loaded) return loaded;
    log("cached demo asset unusable (" + loaded.error() + "); baking it again");
  }
  log("baking the procedural demo lungs (" + std::to_string(o.nodes) + " nodes, once; cached at " + path + ")");
  sim::BakeOptions bake;
  bake.bands = o.bands;
  bake.transfer_rows = o.transfer_rows;
  bake.evaluate = false;
  int last_percent = -1;
  std::string last_stage;
  auto baked = sim::bake_procedural(o.nodes, o.seed, bake, [&](std::string_view stage, double fraction) {
    const int percent = static_cast<int>(fraction * 100.0);
    if (stage != last_stage || percent / 25 != last_percent / 25) {
      last_stage = std::string(stage);
      last_percent = percent;
      log("  bake: " + last_stage + " " + std::to_string(percent) + " %");
    }
  });
  if (!baked) return fail("procedural demo asset: " + baked.error());
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (auto written = sim::write_asset(baked->asset, path); !written) {
    log("could not cache the demo asset (" + written.error() + "); going on without the cache");
  }
  return std::move(baked->asset);
}

}  // namespace lungar::platform
