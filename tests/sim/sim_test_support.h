/// @file sim_test_support.h
/// @brief A small procedural bake shared by the sim tests (baked once per test binary), and temp folders.
#pragma once

#include <filesystem>
#include <random>
#include <string>

#include "sim/bake/bake.h"

namespace lungar::sim::test {

inline constexpr std::uint32_t kSmallNodes = 3000;

/// The procedural pair at kSmallNodes, L = 4, with the report and the truncated rows.
inline const BakeOutput& small_bake() {
  static const BakeOutput out = [] {
    BakeOptions options;
    options.threads = 2;
    Result<BakeOutput> r = bake_procedural(kSmallNodes, 7, options, nullptr);
    if (!r) throw std::runtime_error(r.error());
    return std::move(*r);
  }();
  return out;
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

}  // namespace lungar::sim::test
