/// @file demo_asset.h
/// @brief The asset the runtime draws: the configured `.lungbake`, or the procedural pair baked once and cached.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "sim/asset/baked_asset.h"
#include "config/base/result.h"

namespace lungar::platform {

struct DemoAssetOptions {
  std::uint32_t nodes = 400000;  ///< the paper's size
  std::uint64_t seed = 1;
  std::uint32_t bands = 4;
  bool transfer_rows = false;    ///< explicit rows for --deform cpu1 (a larger bake and file)
  std::string cache_dir;         ///< empty: config::cache_dir() ($LUNGAR_CACHE_DIR, $XDG_CACHE_HOME/lungar, ~/.cache/lungar)
};

/// Where the cached procedural asset for `o` lives.
std::string demo_asset_path(const DemoAssetOptions& o);

/// Loads the cached procedural asset, baking and caching it first when it is missing or unreadable.
/// `log` receives progress lines.
Result<sim::BakedAsset> load_or_bake_demo_asset(const DemoAssetOptions& o,
                                                     const std::function<void(const std::string&)>& log);

}  // namespace lungar::platform
