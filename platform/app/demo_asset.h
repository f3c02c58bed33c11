/// @file demo_asset.h
/// @brief The asset the runtime draws: the configured `.lungbake`; else the demo's real lungs, baked once from the
///        shipped CT label map by the `lungar-bake` executable and cached; or, with --procedural (or when no label
///        map can be found), the procedural pair, baked and cached the same way (in-process when no bake tool is
///        found).
///
/// The runtime links neither ITK nor the mesh library (docs/design.md, Decisions): label maps are read by
/// `lungar-bake`, run here as a child process. It is looked for beside the running `lungar` (an installed layout: one
/// bin/ folder), then at the build tree's path known when lungar was compiled. The label map is looked for in
/// $LUNGAR_DATA_DIR/lungs/, then <exe dir>/../share/lungar/lungs/ (the Debian package), then the source tree's
/// sim/data/lungs/. The cache is $LUNGAR_CACHE_DIR, else $XDG_CACHE_HOME/lungar, else ~/.cache/lungar; its file
/// names carry the asset format version and sim's bake revision, so a changed bake bakes again.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "config/base/result.h"
#include "platform/app/settings.h"
#include "sim/asset/baked_asset.h"
#include "sim/bake/bake.h"

namespace lungar::platform {

/// The label map the demo draws and its lungs' labels (sim/data/lungs/README.md).
inline constexpr const char* kDemoLabelMap = "10002K_INSP_STD_BWH_COPD_leftLungRightLung.nrrd";

struct DemoAssetOptions {
  std::uint32_t nodes = 400000;  ///< the paper's size
  std::uint64_t seed = 1;        ///< of the procedural pair
  std::uint32_t bands = sim::kDefaultBands;
  bool transfer_rows = false;  ///< explicit rows for --deform cpu1 (a larger bake and file)
  bool procedural = false;     ///< the procedural pair instead of the CT lungs
  std::string cache_dir;  ///< empty: config::cache_dir() ($LUNGAR_CACHE_DIR, $XDG_CACHE_HOME/lungar, ~/.cache/lungar)
  std::string data_dir;   ///< empty: the search above; else where lungs/<kDemoLabelMap> is
  std::string bake_tool;  ///< empty: the search above; else the lungar-bake to run
  /// Set (Ctrl-C) while a bake runs: it stops within a second and leaves nothing in the cache; null: never.
  const std::atomic<bool>* stop = nullptr;
};

/// What the runtime draws, and its name for the stats JSON's `asset` (the file, or the cache file's name).
struct DrawnAsset {
  sim::BakedAsset asset;
  std::string name;
  bool demo_ct = false;  ///< the demo's CT lungs (in the scanner's LPS frame, far from its origin)
};

/// The demo's CT lungs sit where the scanner put them (their centre some 24 cm from its origin); with no
/// registration configured (the identity), the demo moves their centre onto the patient tracker, where the
/// procedural pair's is. Returns whether it did.
bool centre_demo_lungs(const DrawnAsset& drawn, RegistrationSettings& registration);

/// Where the cached procedural asset for `o` lives.
std::string demo_asset_path(const DemoAssetOptions& o);

/// Where the demo lungs that `load_drawn_asset("", o)` draws are cached: the CT pair's file when its label map
/// and lungar-bake are found (and `o.procedural` is false), else the procedural pair's. `lungar doctor` looks there.
std::string demo_cache_path(const DemoAssetOptions& o);

/// The asset at `configured_path` when it is not empty; else the demo's (loaded from the cache, or baked and
/// cached first). `log` receives progress lines.
Result<DrawnAsset> load_drawn_asset(const std::string& configured_path, const DemoAssetOptions& o,
                                    const std::function<void(const std::string&)>& log);

/// Loads the cached procedural asset, baking and caching it first when it is missing or unreadable.
Result<sim::BakedAsset> load_or_bake_demo_asset(const DemoAssetOptions& o,
                                                const std::function<void(const std::string&)>& log);

}  // namespace lungar::platform
