/// @file equation_of_motion.h
/// @brief Spontaneous breathing from the single-compartment equation of motion of the respiratory system,
///        P_mus(t) = R dV/dt + (V - V_rel) / C (Otis, Fenn and Rahn, J Appl Physiol 2:592-607, 1950), driven by a
///        muscle pressure that rises through inspiration, relaxes through the first 79 % of expiration and is
///        zero after, so that the rest of expiration is the passive decay of time constant tau = R C.
///
/// The muscle pressure over one breath of period T (neural time s, s = 0 at the onset of inspiratory effort):
///   rise       s in [0, T_rise]:          P = P_peak (1 - cos(pi s / T_rise)) / 2
///   relaxation s in [T_rise, + T_relax]:  P = P_peak (exp(-k q) - exp(-k)) / (1 - exp(-k)),  q = (s - T_rise) / T_relax
///   passive    the rest:                  P = 0
/// The relaxation is the post-inspiratory activity of the diaphragm measured in conscious adults by Shee,
/// Ploysongsang and Milic-Emili (J Appl Physiol 58:1859-1865, 1985): the inspiratory muscle pressure falls to half
/// at 23 % and to zero at 79 % of the expiratory time. So T_relax = 0.79 T_E, and k (about 1.90) puts the half at
/// 0.23 T_E. The rise is a half cosine (zero slope at the onset, so the flow starts smoothly).
///
/// The volume is the periodic steady state of the linear equation, in closed form (no table, no integration): the
/// volume at the end of a breath equals that at its start to rounding. Volumes here are in units of C P_peak, so
/// the shape is independent of the amplitude, which the pattern scales to meet the tidal volume exactly.
///
/// Timing. The configured I:E is the mechanical one, between the zeros of the flow (as a spirometer measures it):
/// phase 0 is the volume minimum, phase ie / (1 + ie) its maximum. The onset of effort precedes the volume minimum
/// (the last of the passive outflow has to be overcome) and the volume peak follows the effort's peak, so solve()
/// chooses T_rise for the mechanical inspiration to take ie / (1 + ie) of the breath. Where no T_rise can (a long
/// tau against a short breath, an extreme I:E), the closest one is taken and the inspiratory and expiratory parts
/// of the cycle are stretched in time to the configured shares, which is the same equation with R scaled in each
/// part (the flow stays continuous: it is zero at both joins).
#pragma once

#include "sim/breathing/pv_curve.h"

namespace lungar::sim {

/// Respiratory-system resistance of a preset, cmH2O.s/L (see equation_of_motion.cpp for the sources).
double respiratory_resistance_cmh2o_s_per_l(Preset preset);

/// Chest-wall compliance, mL/cmH2O: about that of the lungs in a healthy adult near FRC, 200 mL/cmH2O (Agostoni
/// and Hyatt, Static behavior of the respiratory system, Handbook of Physiology, The Respiratory System III, 1986;
/// West, Respiratory Physiology: The Essentials, ch. 7). The same for every preset.
inline constexpr double kChestWallComplianceMlPerCmH2O = 200.0;

/// Compliance of the respiratory system breathing `tidal_volume_ml` from the preset's FRC, mL/cmH2O: the lungs'
/// chord compliance on the preset's curve, V_T / (P(V_FRC + V_T) - P_FRC), in series with the chest wall's.
/// So the preset's pressure-volume curve sets the stiffness: normal about 100, emphysema about 140, fibrosis
/// about 65 mL/cmH2O at V_T = 500 mL.
double respiratory_compliance_ml_per_cmh2o(const PvPreset& preset, double tidal_volume_ml);

/// Share of the expiratory time over which the muscle pressure relaxes to zero, and where it is at half
/// (Shee et al. 1985, above).
inline constexpr double kRelaxationZeroShare = 0.79;
inline constexpr double kRelaxationHalfShare = 0.23;

/// One breath of the equation of motion in periodic steady state, solved by solve_muscle_cycle().
struct MuscleCycle {
  double period_s = 0;
  double inspiratory_share = 0;  ///< ie / (1 + ie): the mechanical inspiration's share of the breath
  double tau_s = 0;              ///< R C
  double rise_s = 0;             ///< T_rise
  double relax_s = 0;            ///< T_relax
  double x_start = 0;            ///< volume (units of C P_peak, above the relaxed volume) at s = 0
  double x_rise_end = 0;         ///< at s = T_rise
  double x_relax_end = 0;        ///< at s = T_rise + T_relax
  double s_min = 0, s_max = 0;   ///< neural times of the volume minimum and maximum
  double x_min = 0, x_max = 0;   ///< the volume there
};

/// The cycle for a period, an inspiratory share in (0, 1) and a time constant, all positive.
MuscleCycle solve_muscle_cycle(double period_s, double inspiratory_share, double tau_s);

/// The muscle pressure at neural time s in [0, period), in units of its peak.
double muscle_pressure(const MuscleCycle& c, double s);
/// The volume at neural time s in [0, period), units of C P_peak above the relaxed volume.
double muscle_cycle_volume(const MuscleCycle& c, double s);
/// The volume at phase u in [0, 1) of the breath, 0 at the minimum (u = 0) and 1 at the maximum
/// (u = inspiratory_share), exactly. Allocates nothing.
double volume_fraction(const MuscleCycle& c, double u);

}  // namespace lungar::sim
