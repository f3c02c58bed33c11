/// @file bench_assets.h
/// @brief The procedural assets a benchmark run draws, baked in-process once and cached with their bake times.
///
/// An asset is keyed by node count, SH bands and whether it carries explicit transfer rows (CPU eq. 1). Beside
/// each cached `.lungbake` a `.bake.json` keeps the bake's timings and the load it ran under, so a rerun that
/// reuses the cache still reports the bake time (marked as not measured in this run).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "config/base/result.h"
#include "sim/asset/baked_asset.h"

namespace lungar::platform::bench {

struct AssetKey {
  std::uint32_t nodes = 400000;
  std::uint32_t bands = 4;
  bool transfer_rows = false;
  double transfer_epsilon = 0;  ///< rows truncated below this fraction of T_II; 0: the bake's default
};

/// How an asset was made; times are 0 (and `known` false) for a cached asset whose record is missing.
struct BakeRecord {
  AssetKey key;
  std::uint32_t vertices = 0;  ///< what the procedural mesh really has (about key.nodes)
  bool known = false;
  bool baked_this_run = false;
  double bake_s = 0, factorise_s = 0, solve_s = 0, transfer_rows_s = 0;
  double transfer_nnz_per_row = 0;
  double load_1min = -1;  ///< load average when the bake finished
  std::string baked_at_utc;
};

struct CachedAsset {
  sim::BakedAsset asset;
  BakeRecord record;
};

/// `dir`/procedural-n<N>-L<B>[-rows].lungbake: loaded when present and sound (and `rebake` false), else baked
/// (seed 1, evaluate off) and written there. `log` gets progress lines.
Result<CachedAsset> load_or_bake(const AssetKey& key, const std::string& dir, bool rebake,
                                 const std::function<void(const std::string&)>& log);

}  // namespace lungar::platform::bench
