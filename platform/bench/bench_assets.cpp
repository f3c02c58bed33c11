/// @file bench_assets.cpp
/// @brief Bake-once cache of benchmark assets, with a JSON record of each bake's timings beside the asset.
#include "platform/bench/bench_assets.h"

#include "config/base/atomic_file.h"
#include "config/base/clock.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "platform/bench/system_info.h"
#include "sim/asset/asset_io.h"
#include "sim/bake/bake.h"

namespace lungar::platform::bench {

namespace {

std::string asset_path(const AssetKey& key, const std::string& dir) {
  char eps[32] = "";
  if (key.transfer_rows && key.transfer_epsilon > 0) std::snprintf(eps, sizeof eps, "-eps%g", key.transfer_epsilon);
  char name[128];
  std::snprintf(name, sizeof name, "procedural-n%u-L%u%s%s-v%u-b%u.lungbake", key.nodes, key.bands,
                key.transfer_rows ? "-rows" : "", eps, sim::kAssetVersion, sim::kBakeRevision);
  return (std::filesystem::path(dir) / name).string();
}

nlohmann::json record_json(const BakeRecord& r) {
  return {{"nodes_requested", r.key.nodes},
          {"bands", r.key.bands},
          {"transfer_rows", r.key.transfer_rows},
          {"transfer_epsilon", r.key.transfer_epsilon},
          {"vertices", r.vertices},
          {"bake_s", r.bake_s},
          {"factorise_s", r.factorise_s},
          {"solve_s", r.solve_s},
          {"transfer_rows_s", r.transfer_rows_s},
          {"transfer_nnz_per_row_mean", r.transfer_nnz_per_row},
          {"load_1min", r.load_1min},
          {"baked_at_utc", r.baked_at_utc}};
}

/// The record beside a cached asset; `known` stays false when it is missing or unreadable.
BakeRecord read_record(const AssetKey& key, const std::string& path) {
  BakeRecord r;
  r.key = key;
  std::ifstream f(path);
  if (!f) return r;
  const nlohmann::json j = nlohmann::json::parse(f, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return r;
  r.bake_s = j.value("bake_s", 0.0);
  r.factorise_s = j.value("factorise_s", 0.0);
  r.solve_s = j.value("solve_s", 0.0);
  r.transfer_rows_s = j.value("transfer_rows_s", 0.0);
  r.transfer_nnz_per_row = j.value("transfer_nnz_per_row_mean", 0.0);
  r.load_1min = j.value("load_1min", -1.0);
  r.baked_at_utc = j.value("baked_at_utc", std::string());
  r.known = r.bake_s > 0;
  return r;
}

}  // namespace

Result<CachedAsset> load_or_bake(const AssetKey& key, const std::string& dir, bool rebake,
                                 const std::function<void(const std::string&)>& log) {
  const std::string path = asset_path(key, dir);
  const std::string record_path = path + ".bake.json";
  std::error_code ec;
  if (!rebake && std::filesystem::exists(path, ec)) {
    auto loaded = sim::load_asset(path);
    if (loaded) {
      CachedAsset out{std::move(*loaded), read_record(key, record_path)};
      out.record.vertices = out.asset.vertex_count();
      return out;
    }
    log("cached asset unusable (" + loaded.error() + "); baking it again");
  }
  log("baking " + std::to_string(key.nodes) + " nodes, " + std::to_string(key.bands) + " bands" +
      (key.transfer_rows ? ", with transfer rows" : "") +
      (key.transfer_epsilon > 0 ? " (epsilon " + std::to_string(key.transfer_epsilon) + ")" : "") + " -> " + path);
  sim::BakeOptions options;
  options.bands = key.bands;
  options.transfer_rows = key.transfer_rows;
  if (key.transfer_epsilon > 0) options.transfer_epsilon = key.transfer_epsilon;
  options.evaluate = false;  // the accuracy figures are the bake tool's job, not the benchmark's
  std::string last_stage;
  auto baked = sim::bake_procedural(key.nodes, 1, options, [&](std::string_view stage, double) {
    if (stage != last_stage) {
      last_stage = std::string(stage);
      log("  bake: " + last_stage);
    }
  });
  if (!baked) return fail("bake of " + path + ": " + baked.error());
  BakeRecord r;
  r.key = key;
  r.vertices = baked->asset.vertex_count();
  r.known = true;
  r.baked_this_run = true;
  r.bake_s = baked->report.bake_s;
  r.factorise_s = baked->report.factorise_s;
  r.solve_s = baked->report.solve_s;
  r.transfer_rows_s = baked->report.transfer_rows_s;
  r.transfer_nnz_per_row = baked->report.transfer_nnz_per_row_mean;
  r.load_1min = load_average_1min();
  r.baked_at_utc = utc_timestamp();
  std::filesystem::create_directories(dir, ec);
  if (auto written = sim::write_asset(baked->asset, path); !written) {
    log("could not cache the asset (" + written.error() + "); going on without the cache");
  } else if (Status recorded = write_file_atomically(record_path, record_json(r).dump(2) + "\n"); !recorded) {
    log("could not record the bake (" + recorded.error() + ")");
  }
  return CachedAsset{std::move(baked->asset), r};
}

}  // namespace lungar::platform::bench
