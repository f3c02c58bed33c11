/// @file sim_test_support.h
/// @brief A small procedural bake shared by the sim tests (baked once per test binary), and temp folders.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>

#include "sim/asset/asset_io.h"
#include "sim/bake/bake.h"

namespace lungar::sim::test {

inline constexpr std::uint32_t kSmallNodes = 3000;

/// The procedural pair at kSmallNodes, L = 4, with the report and the truncated rows, in the paper's model (whose
/// exact eq. (1) the tests solve afresh with the plain stiffness).
inline Result<BakeOutput> bake_small() {
  BakeOptions options;
  options.threads = 2;
  options.model = MotionModel::paper;
  return bake_procedural(kSmallNodes, 7, options, nullptr);
}

inline const BakeOutput& small_bake() {
  static const BakeOutput out = [] {
    Result<BakeOutput> r = bake_small();
    if (!r) throw std::runtime_error(r.error());
    return std::move(*r);
  }();
  return out;
}

inline constexpr std::uint32_t kSlidingNodes = 12000;

/// The sliding bake's options: the procedural pair at kSlidingNodes in the sliding model (the default).
inline Result<BakeOutput> bake_sliding() {
  BakeOptions options;
  options.threads = 2;
  options.bands_sweep = false;
  return bake_procedural(kSlidingNodes, 7, options, nullptr);
}

/// The procedural pair at kSlidingNodes in the sliding model, with the report and the rows, baked in this process.
/// Tests that need only the asset take sliding_asset(), which most processes load instead of baking.
inline const BakeOutput& sliding_bake() {
  static const BakeOutput out = [] {
    Result<BakeOutput> r = bake_sliding();
    if (!r) throw std::runtime_error(r.error());
    return std::move(*r);
  }();
  return out;
}

/// A bake's asset, shared by the test processes of one build of this binary through a file in the build tree
/// (`name` tells the bakes apart). ctest runs every test in a process of its own, and the bake was most of a short
/// test's time: about 8 s of it under AddressSanitizer, in some 50 tests. The file's name carries the binary's size
/// and modification time, so a rebuilt binary (a changed bake, a mutant of scripts/mutate) bakes afresh; it is
/// written under a name of this process's own and renamed into place, and load_asset checks its CRCs, so a torn or
/// stale file is baked again. Tests of the bake's own output, or of the asset's round trip, take the bake itself.
inline BakedAsset shared_bake_asset(const std::string& name, Result<BakeOutput> (*bake)()) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path dir = fs::path(LUNGAR_BINARY_DIR) / "test-cache";
  const std::string prefix = exe.filename().string() + "-" + name + "-";
  std::string key;
  if (!ec) {
    const auto size = fs::file_size(exe, ec);
    const auto mtime = static_cast<unsigned long long>(fs::last_write_time(exe, ec).time_since_epoch().count());
    if (!ec) key = prefix + std::to_string(size) + "-" + std::to_string(mtime) + ".lungbake";
  }
  if (!key.empty()) {
    Result<BakedAsset> cached = load_asset((dir / key).string());
    if (cached) return std::move(*cached);
  }
  Result<BakeOutput> r = bake();
  if (!r) throw std::runtime_error(r.error());
  if (!key.empty()) {
    fs::create_directories(dir, ec);
    const fs::path mine = dir / (key + "." + std::to_string(::getpid()) + ".part");
    if (write_asset(r->asset, mine.string())) fs::rename(mine, dir / key, ec);
    fs::remove(mine, ec);
    for (const auto& e : fs::directory_iterator(dir, ec)) {  // older builds' files
      const std::string file = e.path().filename().string();
      if (file.rfind(prefix, 0) == 0 && file != key && file.find(".part") == std::string::npos)
        fs::remove(e.path(), ec);
    }
  }
  return std::move(r->asset);
}

/// sliding_bake()'s asset, most often loaded from the other test processes' bake (shared_bake_asset).
inline const BakedAsset& sliding_asset() {
  static const BakedAsset asset = shared_bake_asset("sliding-" + std::to_string(kSlidingNodes), bake_sliding);
  return asset;
}

/// small_bake()'s asset, most often loaded from the other test processes' bake (shared_bake_asset).
inline const BakedAsset& small_asset() {
  static const BakedAsset asset = shared_bake_asset("small-" + std::to_string(kSmallNodes), bake_small);
  return asset;
}

/// One lung's surface rebuilt from the asset (what the runtime has), to solve eq. (1) afresh from it.
inline TriMesh lung_mesh(const BakedAsset& a, const BakedLung& lung) {
  TriMesh m;
  for (std::uint32_t i = 0; i < lung.vertex_count; ++i) {
    const float* p = &a.positions[3 * (lung.first_vertex + i)];
    m.positions.emplace_back(p[0], p[1], p[2]);
  }
  for (std::uint32_t t = 0; t < lung.index_count; t += 3) {
    const std::uint32_t* v = &a.triangles[lung.first_index + t];
    m.triangles.push_back({v[0] - lung.first_vertex, v[1] - lung.first_vertex, v[2] - lung.first_vertex});
  }
  return m;
}

/// A fresh, empty folder under the system's temporary folder, removed with the object.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("lungar-sim-test-" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(path_), {}));
  }

 private:
  std::filesystem::path path_;
};

/// Checks a refused bake: `r` failed with one line, and `dir` holds nothing named `out_name` or starting with it
/// (the "<out_name>.partial" a write leaves until it commits).
template <class R>
void expect_refused_cleanly(const R& r, const TempDir& dir, const std::string& out_name) {
  EXPECT_FALSE(r) << "expected a refusal";
  if (r) return;
  EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("")))
    EXPECT_NE(entry.path().filename().string().rfind(out_name, 0), 0u) << entry.path() << " is left";
}

}  // namespace lungar::sim::test
