/// @file pattern.cpp
/// @brief Spontaneous breathing by the equation of motion, the ventilator's pressure waveform, and the amplitudes
///        that meet a tidal volume.
#include "sim/breathing/pattern.h"
#include "config/base/number_text.h"

#include <cmath>

namespace lungar::sim {

namespace {

/// Ventilator in periodic steady state, pressures relative to the low pressure L: during inspiration the alveolar
/// pressure rises toward L + D from x, reaching y; during expiration it falls back toward L from y to x.
/// With A = exp(-Ti/tau), B = exp(-Te/tau): y = D (1 - A) / (1 - A B), x = y B.
struct VentLevels {
  double start, peak;  // x, y (relative to L)
};
VentLevels vent_levels(const BreathingParams& p, double drive) {
  const double period = 60.0 / p.rate_bpm;
  const double ti = period * inspiratory_fraction(p.ie_ratio);
  const double a = std::exp(-ti / p.ventilator_tau_s);
  const double b = std::exp(-(period - ti) / p.ventilator_tau_s);
  const double y = drive * (1.0 - a) / (1.0 - a * b);
  return {y * b, y};
}

/// The ventilator drive pressure whose steady cycle has tidal volume `v_t`, by bisection (volume rises with drive).
/// Returns a negative number when even the largest drive falls short.
double solve_vent_drive(const BreathingParams& p, const PvCurve& curve, double low, double v_t) {
  auto tidal = [&](double drive) {
    const VentLevels l = vent_levels(p, drive);
    return curve.volume_ml(low + l.peak) - curve.volume_ml(low + l.start);
  };
  // The peak alveolar pressure is y = D (1 - A)/(1 - AB) <= D; cap it at kMaxTranspulmonaryCmH2O.
  const VentLevels unit = vent_levels(p, 1.0);
  const double hi_drive = (kMaxTranspulmonaryCmH2O - low) / unit.peak;
  if (hi_drive <= 0 || tidal(hi_drive) < v_t) return -1.0;
  double lo = 0.0, hi = hi_drive;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi_drive; ++i) {
    const double mid = 0.5 * (lo + hi);
    (tidal(mid) < v_t ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

Status validate(const BreathingParams& p) {
  auto bad = [](double v, double lo, double hi) { return !(std::isfinite(v) && v >= lo && v <= hi); };
  if (bad(p.rate_bpm, 2.0, 60.0))
    return fail("rate_bpm: expected [2, 60] breaths/min, got " + number_text(p.rate_bpm, 4));
  if (bad(p.ie_ratio, 0.1, 4.0)) return fail("ie_ratio: expected [0.1, 4], got " + number_text(p.ie_ratio, 4));
  if (bad(p.tidal_volume_ml, 50.0, 3000.0)) {
    return fail("tidal_volume_ml: expected [50, 3000] mL, got " + number_text(p.tidal_volume_ml, 4));
  }
  if (bad(p.ventilator_tau_s, 0.05, 5.0))
    return fail("tau_s: expected [0.05, 5] s, got " + number_text(p.ventilator_tau_s, 4));
  if (bad(p.peep_cmh2o, 0.0, 20.0))
    return fail("peep_cmh2o: expected [0, 20] cmH2O, got " + number_text(p.peep_cmh2o, 4));
  return ok();
}

Status solve(Pattern& pat) {
  if (Status e = validate(pat.params); !e) return e;
  const PvPreset& preset = pv_preset(pat.params.preset);
  const PvCurve& curve = preset.curve;
  pat.v_frc_ml = preset.frc_ml();
  const double low = preset.p_frc_cmh2o + (pat.params.mode == Mode::Ventilator ? pat.params.peep_cmh2o : 0.0);
  pat.p_low_cmh2o = low;

  auto reach_error = [&](const char* what, double wanted) {
    return std::string(what) + ": expected at most " + number_text(max_tidal_volume_ml(preset, low), 4) +
           " mL on the " + std::string(to_string(preset.id)) + " curve (its volume at " +
           number_text(kMaxTranspulmonaryCmH2O, 4) + " cmH2O less that at " + number_text(low, 4) + " cmH2O), got " +
           number_text(wanted, 4) + " mL";
  };
  // Spontaneous: V(low + swing) - V(low) = V_T, solved in closed form by the inverse of the sigmoid.
  auto spontaneous_swing = [&](double v_t) {
    return curve.pressure_cmh2o(curve.volume_ml(low) + v_t) - low;
  };
  const double reach = max_tidal_volume_ml(preset, low);

  if (pat.params.mode == Mode::Spontaneous) {
    if (pat.params.tidal_volume_ml > reach) return fail(reach_error("tidal_volume_ml", pat.params.tidal_volume_ml));
    pat.swing_cmh2o = spontaneous_swing(pat.params.tidal_volume_ml);
    // The equation of motion: R of the preset, C from its curve at this tidal volume; the muscle pressure's peak
    // is what moves V_T through the cycle's volume range (units of C P_peak).
    const double period = 60.0 / pat.params.rate_bpm;
    pat.resistance_cmh2o_s_per_l = respiratory_resistance_cmh2o_s_per_l(pat.params.preset);
    pat.compliance_ml_per_cmh2o = respiratory_compliance_ml_per_cmh2o(preset, pat.params.tidal_volume_ml);
    const double tau = pat.resistance_cmh2o_s_per_l * pat.compliance_ml_per_cmh2o * 1e-3;
    pat.cycle = solve_muscle_cycle(period, inspiratory_fraction(pat.params.ie_ratio), tau);
    pat.pmus_peak_cmh2o =
        pat.params.tidal_volume_ml / (pat.compliance_ml_per_cmh2o * (pat.cycle.x_max - pat.cycle.x_min));
    pat.sigh_swing_cmh2o = 0;
    pat.sigh_cycle = pat.cycle;
    if (pat.sigh_breath >= 0) {
      if (pat.sigh_volume_ml > reach) return fail(reach_error("sigh volume_ml", pat.sigh_volume_ml));
      pat.sigh_swing_cmh2o = spontaneous_swing(pat.sigh_volume_ml);
      // The sigh is a breath of its own depth: C (so tau) at its volume, as steady breathing at that depth.
      const double c_sigh = respiratory_compliance_ml_per_cmh2o(preset, pat.sigh_volume_ml);
      pat.sigh_cycle = solve_muscle_cycle(period, inspiratory_fraction(pat.params.ie_ratio),
                                          pat.resistance_cmh2o_s_per_l * c_sigh * 1e-3);
    }
    pat.vent_start_cmh2o = pat.vent_peak_cmh2o = low;
  } else {
    if (pat.sigh_breath >= 0) return fail("sigh: expected spontaneous breathing, got a sigh on the ventilator");
    const double drive = solve_vent_drive(pat.params, curve, low, pat.params.tidal_volume_ml);
    if (drive < 0) return fail(reach_error("tidal_volume_ml", pat.params.tidal_volume_ml));
    pat.swing_cmh2o = drive;
    const VentLevels l = vent_levels(pat.params, drive);
    pat.vent_start_cmh2o = low + l.start;
    pat.vent_peak_cmh2o = low + l.peak;
  }
  return ok();
}

PatternPoint evaluate(const Pattern& pat, double phase) {
  const PvCurve& curve = pv_preset(pat.params.preset).curve;
  const double breath = std::floor(phase);
  const double u = phase - breath;  // position in the cycle, [0, 1)
  const double rho = inspiratory_fraction(pat.params.ie_ratio);
  const double low = pat.p_low_cmh2o;
  if (pat.apnoea) return {low, low, curve.volume_ml(low)};

  if (pat.params.mode == Mode::Spontaneous) {
    // The equation of motion's breath, scaled to the tidal volume: FRC at u = 0 (and 1), FRC + V_T at u = rho. A
    // sigh is a breath solved at its own depth (flow is zero at both ends of every breath, so it joins its
    // neighbours smoothly).
    const bool sigh = pat.sigh_breath >= 0 && static_cast<std::int64_t>(breath) == pat.sigh_breath;
    const double v_t = sigh ? pat.sigh_volume_ml : pat.params.tidal_volume_ml;
    const double v = pat.v_frc_ml + v_t * volume_fraction(sigh ? pat.sigh_cycle : pat.cycle, u);
    const double p = curve.pressure_cmh2o(v);
    return {p, p, v};
  }
  // Ventilator: square applied pressure, exponential approach of the alveolar pressure (time constant tau).
  const double period = 60.0 / pat.params.rate_bpm;
  const double tau = pat.params.ventilator_tau_s;
  const double high = low + pat.swing_cmh2o;
  double p = 0, applied = 0;
  if (u < rho) {
    applied = high;
    p = high - (high - pat.vent_start_cmh2o) * std::exp(-u * period / tau);
  } else {
    applied = low;
    p = low + (pat.vent_peak_cmh2o - low) * std::exp(-(u - rho) * period / tau);
  }
  return {p, applied, curve.volume_ml(p)};
}

}  // namespace lungar::sim
