/// @file bench_run.h
/// @brief lungar-bench's whole run: the paper's Table II and Figs. 4, 6 and 7, the stereo strategies, level of
/// detail on and off, the CPU deformation alone and bake times, measured in one process and written as JSON.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "render/drawable_options.h"

namespace lungar::platform::bench {

/// The parts of a run, in the order they run (grouped by asset so that each asset is loaded once).
inline const std::vector<std::string> kSections = {"table2", "cpu", "strategies", "fig7", "fig4", "fig6"};

struct BenchOptions {
  bool quick = false;       ///< 50k nodes, fewer point sizes, shorter repetitions
  std::uint32_t nodes = 0;  ///< the 1x model; 0: 400000 (the paper's), or 50000 with quick
  int reps = 5;
  double rep_s = 0;     ///< 0: 0.3 s, or 0.1 s with quick
  double warmup_s = 0;  ///< 0: 0.5 s, or 0.15 s with quick
  std::string json_path = "bench.json";
  std::string asset_dir = "bench-assets";
  std::string snapshot_dir;  ///< PNGs of the timed frames; empty: none
  bool rebake = false;       ///< bake every asset again even when cached (fresh bake times)
  /// Also CPU eq. (1) with rows truncated at this fraction of T_II (denser: 0.0065 keeps 191 a row at 400k,
  /// the paper had 192); 0: not; unset: 0.0065, or 0 with quick (the denser rows take minutes to bake).
  std::optional<double> eq1_epsilon;
  bool bake_only = false;          ///< fill the asset cache (and record bake times), measure no frames
  std::set<std::string> sections;  ///< empty: all of kSections
  /// Where the coefficients live on the GPU; Auto is what the program uses (render/lung_drawable.h).
  render::CoeffStorage storage = render::CoeffStorage::Auto;
  std::vector<std::uint32_t> fig6_bands;  ///< Fig. 6's band counts; empty: 2 .. 8
};

/// Runs the benchmark; progress goes to stderr. Returns the process exit code (0, or 1 with one error line).
int run_bench(const BenchOptions& options);

}  // namespace lungar::platform::bench
