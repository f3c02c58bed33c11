/// @file sim_test_support.h
/// @brief A small procedural bake shared by the sim tests (baked once per test binary), and temp folders.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "sim/bake/bake.h"

namespace lungar::sim::test {

inline constexpr std::uint32_t kSmallNodes = 3000;

/// The procedural pair at kSmallNodes, L = 4, with the report and the truncated rows, in the paper's model (whose
/// exact eq. (1) the tests solve afresh with the plain stiffness).
inline const BakeOutput& small_bake() {
  static const BakeOutput out = [] {
    BakeOptions options;
    options.threads = 2;
    options.model = MotionModel::paper;
    Result<BakeOutput> r = bake_procedural(kSmallNodes, 7, options, nullptr);
    if (!r) throw std::runtime_error(r.error());
    return std::move(*r);
  }();
  return out;
}

inline constexpr std::uint32_t kSlidingNodes = 12000;

/// The procedural pair at kSlidingNodes in the sliding model (the default), with the report and the rows.
inline const BakeOutput& sliding_bake() {
  static const BakeOutput out = [] {
    BakeOptions options;
    options.threads = 2;
    options.bands_sweep = false;
    Result<BakeOutput> r = bake_procedural(kSlidingNodes, 7, options, nullptr);
    if (!r) throw std::runtime_error(r.error());
    return std::move(*r);
  }();
  return out;
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
