/// @file bench_targets.h
/// @brief The issues' targets, kept typed as they are measured and judged once at the end of a run.
/// @ingroup bench
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

namespace lungar::platform::bench {

struct BenchTargets {
  std::optional<double> stereo_over_mono_paired;   ///< median of interleaved ratios
  std::optional<double> mono_ms, stereo_ms;        ///< Table II, GPU eq. (7), points (fallback ratio, frame time)
  std::optional<double> deformed_over_undeformed;  ///< median of interleaved ratios, the paper's 16 coefficients
  std::optional<double> deformed_over_undeformed_default_coefficients;  ///< the same at the bake's default (Fig. 6)
  std::optional<double> eq1_over_eq7;                                   ///< CPU step alone, the bake's default rows
  std::optional<double> eq1_over_eq7_denser, denser_nnz_per_row;
  std::optional<double> small_ms, large_ms;  ///< Fig. 4, GPU eq. (7), LOD on, at 0.25x and 4x nodes

  /// {name: {value, limit_min|limit_max, met, what}} for each target that was measured.
  nlohmann::json to_json() const;
};

}  // namespace lungar::platform::bench
