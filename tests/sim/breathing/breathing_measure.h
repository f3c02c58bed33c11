/// @file breathing_measure.h
/// @brief Test helpers that measure a breathing trace the way one would on a spirometer: per-breath tidal
///        volume, period from mid-level crossings, and the largest step between samples.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sim/breathing/driver.h"

namespace lungar::sim::testing {

/// The driver for `p`, shared by the breathing suites; the test fails when `p` is refused.
inline BreathingDriver make(const BreathingParams& p) {
  auto c = BreathingDriver::create(p);
  EXPECT_TRUE(c) << c.error();
  return std::move(*c);
}

inline std::vector<BreathingSample> trace(const BreathingDriver& d, double t0, double t1, double dt) {
  std::vector<BreathingSample> out;
  const auto n = static_cast<long>(std::floor((t1 - t0) / dt));
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (long k = 0; k <= n; ++k) out.push_back(d.at(t0 + static_cast<double>(k) * dt));
  return out;
}

/// Peak-to-trough volume in each window [t0 + k T, t0 + (k+1) T), k < breaths.
inline std::vector<double> tidal_volumes(const BreathingDriver& d, double t0, double period, int breaths,
                                         double dt) {
  std::vector<double> out;
  for (int k = 0; k < breaths; ++k) {
    double lo = 1e300, hi = -1e300;
    for (const BreathingSample& s : trace(d, t0 + k * period, t0 + (k + 1) * period, dt)) {
      lo = std::min(lo, s.v_ml);
      hi = std::max(hi, s.v_ml);
    }
    out.push_back(hi - lo);
  }
  return out;
}

/// Times where the volume rises through `level`, linearly interpolated between samples.
inline std::vector<double> rising_crossings(const std::vector<BreathingSample>& tr, double level) {
  std::vector<double> out;
  for (std::size_t k = 1; k < tr.size(); ++k) {
    const double a = tr[k - 1].v_ml - level, b = tr[k].v_ml - level;
    if (a < 0 && b >= 0) out.push_back(tr[k - 1].t_s + (tr[k].t_s - tr[k - 1].t_s) * (-a) / (b - a));
  }
  return out;
}

/// The largest |V(t + dt) - V(t)| over a trace.
inline double max_step_ml(const std::vector<BreathingSample>& tr) {
  double m = 0;
  for (std::size_t k = 1; k < tr.size(); ++k) m = std::max(m, std::abs(tr[k].v_ml - tr[k - 1].v_ml));
  return m;
}

/// The largest step |V(t + dt) - V(t)| of steady breathing with `params`, over one breath and every alignment
/// of the samples (t on a grid 50 times finer than dt).
inline double steady_max_step_ml(const BreathingParams& params, double dt) {
  auto c = BreathingDriver::create(params);
  if (!c) return 0;
  const double period = 60.0 / params.rate_bpm;
  double m = 0;
  for (double t = 0; t < period; t += dt / 50.0) m = std::max(m, std::abs(c->at(t + dt).v_ml - c->at(t).v_ml));
  return m;
}

}  // namespace lungar::sim::testing
