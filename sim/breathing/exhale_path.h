/// @file exhale_path.h
/// @brief How far expiration has gone at 10, 20, 30 and 40 % of the breath, measured on the driver the way 4-D CT
///        measures it, and the 4-D CT figures to hold it against.
///
/// The figure at x is (V_peak - V(t_peak + x T)) / (V_peak - V(t_peak + T / 2)): the share of the path from the
/// end-inhale volume (4-D CT phase T00) to the volume half a breath later (T50) covered at T10, T20, T30, T40;
/// t_peak is the time of the end-inhale volume maximum, T the breath period.
#pragma once

#include <array>

#include "config/base/result.h"
#include "sim/breathing/pattern.h"

namespace lungar::sim {

/// The mean figures of DIR-Lab's ten supine 4-D CT cases (Castillo et al., Phys Med Biol 54:1849-1870, 2009), at
/// 10, 20, 30, 40 % of the breath after end-inhale: expiration starts slowly, then follows a decay.
inline constexpr std::array<double, 4> kExhalePath4dct = {0.15, 0.50, 0.73, 0.89};

struct ExhalePath {
  std::array<double, 4> path{};        ///< at 10, 20, 30, 40 % of the breath after the volume peak
  double t_peak_s = 0;                 ///< the end-inhale volume maximum (within the measured breath)
  double tidal_volume_ml = 0;          ///< max - min of V over that breath
};

/// Steady breathing with `params` (no events), measured over its fourth breath, sampled every T / 20000; or why
/// `params` are unusable.
Result<ExhalePath> measure_exhale_path(const BreathingParams& params);

}  // namespace lungar::sim
