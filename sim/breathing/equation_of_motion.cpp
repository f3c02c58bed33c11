/// @file equation_of_motion.cpp
/// @brief The preset's resistance and compliance, and the closed-form periodic steady state of
///        tau dx/ds + x = P_mus(s) over one breath.
#include "sim/breathing/equation_of_motion.h"

#include <cmath>
#include <numbers>

namespace lungar::sim {

namespace {

// Resistance of the respiratory system (airways, lung and chest-wall tissue), cmH2O.s/L.
//
// Normal: healthy adults breathing quietly have 2-4 cmH2O.s/L, about half of it in the airways and the rest in the
// lung and chest-wall tissue (D'Angelo et al., J Appl Physiol 67:2556-2564, 1989). 3.5 is the value in that range
// that puts the default exhale path closest to 4-D CT (docs/design.md, "Pressure-volume"; tau = R C = 0.36 s).
//
// Emphysema: the destroyed parenchyma no longer holds the small airways open and they narrow, most in expiration
// (West, Pulmonary Pathophysiology, ch. 4): three times normal. With its larger compliance, tau is about 1.5 s,
// so expiration is slower and, at a fast rate, ends above the relaxed volume (intrinsic PEEP).
//
// Fibrosis: the stiff parenchyma pulls the airways open, so their resistance stays normal (West, Pulmonary
// Pathophysiology, ch. 5); the low compliance alone makes tau short (about 0.23 s).
constexpr double kNormalResistance = 3.5;
constexpr double kEmphysemaResistance = 3.0 * kNormalResistance;
constexpr double kFibrosisResistance = kNormalResistance;

/// The relaxation's rate k: (exp(-k a) - exp(-k)) / (1 - exp(-k)) = 1/2 with a = 0.23 / 0.79 (the half-way point
/// of the relaxation), by bisection; the left side falls as k grows. About 1.90.
double relaxation_rate() {
  const double a = kRelaxationHalfShare / kRelaxationZeroShare;
  double lo = 1e-6, hi = 50.0;
  for (int i = 0; i < 200; ++i) {
    const double k = 0.5 * (lo + hi);
    const double level = (std::exp(-k * a) - std::exp(-k)) / -std::expm1(-k);
    (level > 0.5 ? lo : hi) = k;
  }
  return 0.5 * (lo + hi);
}

double rate_k() {
  static const double k = relaxation_rate();
  return k;
}

/// (exp(z) - 1) / z, 1 at z = 0, without cancellation.
double expm1_over(double z) { return std::abs(z) < 1e-300 ? 1.0 : std::expm1(z) / z; }

/// tau x' + x = (1 - cos(w s)) / 2 from x(0) = x0: the particular solution plus the decay of the difference.
double rise_volume(double x0, double s, double rise, double tau) {
  const double w = std::numbers::pi / rise, wt = w * tau, den = 1.0 + wt * wt;
  const double particular = 0.5 - 0.5 * (std::cos(w * s) + wt * std::sin(w * s)) / den;
  const double particular0 = 0.5 - 0.5 / den;
  return particular + (x0 - particular0) * std::exp(-s / tau);
}

/// tau x' + x = alpha exp(-q/tr) - beta from x(0) = x1, q the time since the peak, tr = T_relax / k:
///   x = x1 e^(-q/tau) - beta (1 - e^(-q/tau)) + (alpha / tau) q e^(-q/tau) psi(c q),  c = 1/tau - 1/tr,
/// with psi(z) = (e^z - 1)/z; where c q is large the last term is computed as (e^(-q/tr) - e^(-q/tau)) / (c tau).
double relax_volume(double x1, double q, double relax, double tau) {
  const double k = rate_k();
  const double alpha = 1.0 / -std::expm1(-k), beta = alpha * std::exp(-k);
  const double tr = relax / k;
  const double c = 1.0 / tau - 1.0 / tr;
  const double decay = std::exp(-q / tau);
  const double z = c * q;
  const double forced = z < 1.0 ? q * decay * expm1_over(z) / tau : (std::exp(-q / tr) - decay) / (c * tau);
  return x1 * decay - beta * -std::expm1(-q / tau) + alpha * forced;
}

/// The volume at the three joins for a start x0 (linear in x0).
struct Joins {
  double rise_end, relax_end, period_end;
};
Joins propagate(double x0, double period, double rise, double relax, double tau) {
  Joins j;
  j.rise_end = rise_volume(x0, rise, rise, tau);
  j.relax_end = relax_volume(j.rise_end, relax, relax, tau);
  j.period_end = j.relax_end * std::exp(-(period - rise - relax) / tau);
  return j;
}

/// Bisection for the zero of the flow's sign, P(s) - x(s), on [lo, hi] where it goes from `rising` sign to the other.
double flow_zero(const MuscleCycle& c, double lo, double hi, bool rising) {
  for (int i = 0; i < 200 && hi - lo > 1e-13 * c.period_s; ++i) {
    const double mid = 0.5 * (lo + hi);
    const bool positive = muscle_pressure(c, mid) - muscle_cycle_volume(c, mid) > 0;
    (positive == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The periodic cycle for a given T_rise, with its volume extremes.
MuscleCycle cycle_for(double period, double share, double tau, double rise, double relax) {
  MuscleCycle c{.period_s = period, .inspiratory_share = share, .tau_s = tau, .rise_s = rise, .relax_s = relax};
  // x(T) = x0 e^(-T/tau) + x(T) from rest, and x(T) = x0 in steady state.
  const double from_rest = propagate(0.0, period, rise, relax, tau).period_end;
  c.x_start = from_rest / -std::expm1(-period / tau);
  const Joins j = propagate(c.x_start, period, rise, relax, tau);
  c.x_rise_end = j.rise_end;
  c.x_relax_end = j.relax_end;
  // The flow, (P - x)/tau, is -x0/tau < 0 at s = 0 and (1 - x)/tau > 0 at the peak of effort: the minimum lies in the
  // rise. It is negative again when the relaxation ends (P = 0 < x): the maximum lies in the relaxation.
  c.s_min = flow_zero(c, 0.0, rise, true);
  c.s_max = flow_zero(c, rise, rise + relax, false);
  c.x_min = muscle_cycle_volume(c, c.s_min);
  c.x_max = muscle_cycle_volume(c, c.s_max);
  return c;
}

}  // namespace

double respiratory_resistance_cmh2o_s_per_l(Preset preset) {
  switch (preset) {
    case Preset::Normal: return kNormalResistance;
    case Preset::Emphysema: return kEmphysemaResistance;
    case Preset::Fibrosis: return kFibrosisResistance;
  }
  return kNormalResistance;
}

double respiratory_compliance_ml_per_cmh2o(const PvPreset& preset, double tidal_volume_ml) {
  const double swing = preset.curve.pressure_cmh2o(preset.frc_ml() + tidal_volume_ml) - preset.p_frc_cmh2o;
  const double lung = tidal_volume_ml / swing;
  return 1.0 / (1.0 / lung + 1.0 / kChestWallComplianceMlPerCmH2O);
}

double muscle_pressure(const MuscleCycle& c, double s) {
  if (s < c.rise_s) return 0.5 * (1.0 - std::cos(std::numbers::pi * s / c.rise_s));
  const double q = s - c.rise_s;
  if (q < c.relax_s) {
    const double k = rate_k();
    return (std::exp(-k * q / c.relax_s) - std::exp(-k)) / -std::expm1(-k);
  }
  return 0.0;
}

double muscle_cycle_volume(const MuscleCycle& c, double s) {
  if (s < c.rise_s) return rise_volume(c.x_start, s, c.rise_s, c.tau_s);
  const double q = s - c.rise_s;
  if (q < c.relax_s) return relax_volume(c.x_rise_end, q, c.relax_s, c.tau_s);
  return c.x_relax_end * std::exp(-(q - c.relax_s) / c.tau_s);
}

MuscleCycle solve_muscle_cycle(double period, double share, double tau) {
  const double relax = kRelaxationZeroShare * (1.0 - share) * period;
  // The mechanical inspiration (s_max - s_min) grows with T_rise; bisect T_rise for it to take `share` of the
  // period, within [1 %, all that the relaxation leaves] of the period.
  double lo = 0.01 * period, hi = period - relax;
  auto mechanical = [&](double rise) {
    const MuscleCycle c = cycle_for(period, share, tau, rise, relax);
    return (c.s_max - c.s_min) / period;
  };
  if (mechanical(hi) <= share) {
    lo = hi;
  } else if (mechanical(lo) >= share) {
    hi = lo;
  } else {
    for (int i = 0; i < 100 && hi - lo > 1e-12 * period; ++i) {
      const double mid = 0.5 * (lo + hi);
      (mechanical(mid) < share ? lo : hi) = mid;
    }
  }
  return cycle_for(period, share, tau, 0.5 * (lo + hi), relax);
}

double volume_fraction(const MuscleCycle& c, double u) {
  // Phase to neural time: [0, share) onto [s_min, s_max), [share, 1) onto [s_max, s_min + T); the identity in time
  // wherever solve_muscle_cycle met the share (then s_max - s_min = share T).
  const double inspiration = c.s_max - c.s_min;
  const double share = c.inspiratory_share;
  double s = u < share ? c.s_min + u / share * inspiration
                       : c.s_max + (u - share) / (1.0 - share) * (c.period_s - inspiration);
  if (s >= c.period_s) s -= c.period_s;
  return (muscle_cycle_volume(c, s) - c.x_min) / (c.x_max - c.x_min);
}

}  // namespace lungar::sim
