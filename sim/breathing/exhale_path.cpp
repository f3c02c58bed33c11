/// @file exhale_path.cpp
/// @brief The exhale path of steady breathing, sampled on the driver.
#include "sim/breathing/exhale_path.h"

#include <algorithm>

#include "sim/breathing/driver.h"

namespace lungar::sim {

Result<ExhalePath> measure_exhale_path(const BreathingParams& params) {
  auto created = BreathingDriver::create(params);
  if (!created) return fail(created.error());
  const BreathingDriver& d = *created;
  const double period = 60.0 / params.rate_bpm;
  const double t0 = 3.0 * period;
  constexpr int kSamples = 20000;
  ExhalePath out;
  double v_peak = -1e300, v_low = 1e300;
  for (int k = 0; k < kSamples; ++k) {
    const double t = t0 + period * k / kSamples;
    const double v = d.at(t).v_ml;
    if (v > v_peak) v_peak = v, out.t_peak_s = t;
    v_low = std::min(v_low, v);
  }
  out.tidal_volume_ml = v_peak - v_low;
  const double half = v_peak - d.at(out.t_peak_s + 0.5 * period).v_ml;
  for (std::size_t i = 0; i < out.path.size(); ++i) {
    const double x = 0.1 * static_cast<double>(i + 1);
    out.path[i] = (v_peak - d.at(out.t_peak_s + x * period).v_ml) / half;
  }
  return out;
}

}  // namespace lungar::sim
