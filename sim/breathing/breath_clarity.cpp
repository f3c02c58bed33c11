/// @file breath_clarity.cpp
/// @brief The breathing band's share of a trace's power (breath_clarity.h), by a direct DFT of at most 600 points.
#include "sim/breathing/breath_clarity.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace lungar::sim {

double breathing_clarity(const BreathTrace& trace, double window_s) {
  const std::vector<TraceSample>& s = trace.samples;
  if (s.size() < 2) return 0.0;
  constexpr double kRateHz = 10.0;
  const double span = std::min(window_s, s.back().t_s - s.front().t_s);
  const auto n = static_cast<std::size_t>(span * kRateHz);
  if (n < 16) return 0.0;
  std::vector<double> x(n);
  std::size_t j = 0;
  double mean = 0;
  for (std::size_t i = 0; i < n; ++i) {  // linear interpolation at 10 Hz
    const double t = s.front().t_s + static_cast<double>(i) / kRateHz;
    while (j + 2 < s.size() && s[j + 1].t_s < t) ++j;
    const double u = std::clamp((t - s[j].t_s) / (s[j + 1].t_s - s[j].t_s), 0.0, 1.0);
    mean += x[i] = s[j].value + u * (s[j + 1].value - s[j].value);
  }
  mean /= static_cast<double>(n);
  double band = 0, total = 0;
  for (std::size_t k = 1; k <= n / 2; ++k) {
    const double f = static_cast<double>(k) * kRateHz / static_cast<double>(n);
    if (f < 0.02) continue;
    std::complex<double> c = 0;
    for (std::size_t i = 0; i < n; ++i)
      c += (x[i] - mean) * std::polar(1.0, -2.0 * M_PI * static_cast<double>(k * i) / static_cast<double>(n));
    const double power = std::norm(c);
    total += power;
    band += f >= kBreathingBandHz[0] && f <= kBreathingBandHz[1] ? power : 0.0;
  }
  return total > 0 ? band / total : 0.0;
}

std::size_t clearest_breathing(const std::vector<BreathTrace>& traces, std::vector<double>* clarity) {
  std::size_t best = 0;
  double best_share = -1;
  if (clarity) clarity->clear();
  for (std::size_t i = 0; i < traces.size(); ++i) {
    const double share = breathing_clarity(traces[i]);
    if (clarity) clarity->push_back(share);
    if (share > best_share) best = i, best_share = share;
  }
  return best;
}

}  // namespace lungar::sim
