/// @file pattern.h
/// @brief One steady breathing pattern: the user's parameters, what is solved from them (the muscle pressure's
///        cycle, or the ventilator's pressures), and the pressure and volume at any point of the breathing cycle.
///
/// The cycle is measured by a phase: breath k is phase [k, k + 1); inspiration takes the first
/// ie / (1 + ie) of it. The driver (driver.h) turns time into phase; a pattern turns phase into volume and pressure.
/// Spontaneous breathing follows the equation of motion (equation_of_motion.h): the volume starts each breath at
/// the FRC, reaches FRC + V_T at the end of inspiration and is periodic; the pressure is the preset's curve at that
/// volume, P(V), so the curve still sets how much pressure a breath takes.
#pragma once

#include "config/base/result.h"

#include <cstdint>
#include <string>

#include "sim/breathing/equation_of_motion.h"
#include "sim/breathing/pv_curve.h"

namespace lungar::sim {

enum class Mode {
  Spontaneous,  ///< muscle pressure through the single-compartment equation of motion (equation_of_motion.h)
  Ventilator,   ///< square applied pressure; alveolar pressure follows it with a first-order lag
};

/// What a user sets. Ranges are those of config/breathing_settings.cpp.
struct BreathingParams {
  Preset preset = Preset::Normal;
  double rate_bpm = 12.0;          ///< breaths per minute, [2, 60]
  double ie_ratio = 0.5;           ///< inspiration : expiration time, [0.1, 4]
  double tidal_volume_ml = 500.0;  ///< target tidal volume, [50, 3000] mL and within the curve's reach
  Mode mode = Mode::Spontaneous;
  /// Ventilator only: the respiratory system's time constant R*C, s. About 0.5 s for a sedated adult on a
  /// ventilator (R about 10 cmH2O.s/L with the tube, C about 50 mL/cmH2O; Lucangelo et al., Respir Care
  /// 50:55-67, 2005).
  double ventilator_tau_s = 0.5;
  double peep_cmh2o = 0.0;         ///< ventilator only: end-expiratory pressure added on top of the preset's
};

/// Empty when `p` is usable, else what is wrong, e.g. "tidal_volume_ml: expected at most 2077 mL on the ...".
Status validate(const BreathingParams& p);

/// A pattern: parameters, transient state (hold, apnoea, a sigh to come) and what is solved from them.
struct Pattern {
  BreathingParams params;
  bool held = false;                ///< breath hold: the phase stands still
  bool apnoea = false;              ///< no breathing: the swing is zero
  std::int64_t sigh_breath = -1;    ///< the breath (phase index) that is a sigh; -1: none
  double sigh_volume_ml = 0.0;

  // Solved by solve():
  double p_low_cmh2o = 0;        ///< end-expiratory (spontaneous) or low applied (ventilator) pressure
  double swing_cmh2o = 0;        ///< transpulmonary pressure swing for the tidal volume (ventilator: the drive)
  double sigh_swing_cmh2o = 0;   ///< the same for the sigh
  double vent_start_cmh2o = 0;   ///< ventilator: alveolar pressure at the start and end of inspiration
  double vent_peak_cmh2o = 0;
  double v_frc_ml = 0;           ///< the preset's FRC
  // Spontaneous only, solved by solve():
  double resistance_cmh2o_s_per_l = 0;  ///< the preset's R
  double compliance_ml_per_cmh2o = 0;   ///< the respiratory system's C at this tidal volume (from the curve)
  double pmus_peak_cmh2o = 0;           ///< the muscle pressure's peak for the tidal volume
  MuscleCycle cycle;                    ///< the equation of motion's periodic breath, tau = R C
  MuscleCycle sigh_cycle;               ///< the same for the sigh (C at the sigh's volume)
};

/// Solves the swing(s) of `pattern` in place; returns empty, or why the targets cannot be met.
Status solve(Pattern& pattern);

/// Pressures and volume of a pattern at one phase.
struct PatternPoint {
  double p_cmh2o;          ///< transpulmonary (alveolar) pressure: the preset's curve at v_ml
  double p_applied_cmh2o;  ///< the driving pressure: equals p for spontaneous breathing, square on a ventilator
  double v_ml;
};
PatternPoint evaluate(const Pattern& pattern, double phase);

/// Fraction of the cycle spent in inspiration.
inline double inspiratory_fraction(double ie_ratio) { return ie_ratio / (1.0 + ie_ratio); }

}  // namespace lungar::sim
