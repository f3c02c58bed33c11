/// @file pv_curve.h
/// @brief The sigmoid pressure-volume relation of the lungs (stage 1 of the paper) and its three presets.
///
/// V(P) = a + b / (1 + exp(-(P - c) / d))  (Venegas, Harris and Simon, J Appl Physiol 84:389-395, 1998),
/// with P the transpulmonary pressure in cmH2O and V the lung volume in mL.
#pragma once

#include <optional>
#include <string_view>

#include "config/base/patient_names.h"

namespace lungar::sim {

/// Venegas' four parameters: a the lower asymptote (mL), b the distance between the asymptotes (mL), c the
/// pressure of the inflection point where compliance is highest (cmH2O), d the width of the steep part (cmH2O).
struct PvCurve {
  double a_ml = 0;
  double b_ml = 0;
  double c_cmh2o = 0;
  double d_cmh2o = 1;

  /// V(P), mL.
  double volume_ml(double p_cmh2o) const;
  /// The inverse, P(V), cmH2O; `v_ml` must lie strictly between the asymptotes a and a + b.
  double pressure_cmh2o(double v_ml) const;
  /// dV/dP at P, mL/cmH2O.
  double compliance_ml_per_cmh2o(double p_cmh2o) const;
};

using lungar::Preset;  // config/base/patient_names.h: the names are spelled there
inline constexpr Preset kAllPresets[] = {Preset::Normal, Preset::Emphysema, Preset::Fibrosis};

/// A curve and the relaxed end-expiratory transpulmonary pressure on it; V(p_frc) is the FRC.
struct PvPreset {
  Preset id;  ///< its name: to_string(id), spelled in config/base/patient_names.h
  PvCurve curve;
  double p_frc_cmh2o;     ///< transpulmonary pressure at the end of a quiet expiration

  double frc_ml() const { return curve.volume_ml(p_frc_cmh2o); }
};

/// The largest transpulmonary pressure the driver applies, cmH2O: total lung capacity is reached at about
/// 30-40 cmH2O in healthy adults (West, Respiratory Physiology: The Essentials, ch. 7), so V(40) stands for TLC.
inline constexpr double kMaxTranspulmonaryCmH2O = 40.0;

const PvPreset& pv_preset(Preset preset);
std::optional<Preset> preset_from_name(std::string_view name);
std::string_view to_string(Preset preset);

/// The largest tidal volume the preset can breathe from its FRC without passing kMaxTranspulmonaryCmH2O, mL.
double max_tidal_volume_ml(const PvPreset& preset, double start_pressure_cmh2o);

}  // namespace lungar::sim
