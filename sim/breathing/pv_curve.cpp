/// @file pv_curve.cpp
/// @brief The Venegas sigmoid and the parameters of the normal, emphysematous and fibrotic presets.
#include "sim/breathing/pv_curve.h"

#include <cmath>

namespace lungar::sim {

double PvCurve::volume_ml(double p) const { return a_ml + b_ml / (1.0 + std::exp(-(p - c_cmh2o) / d_cmh2o)); }

double PvCurve::pressure_cmh2o(double v) const {
  // Solve v = a + b / (1 + e) for e = exp(-(P - c)/d).
  return c_cmh2o - d_cmh2o * std::log(b_ml / (v - a_ml) - 1.0);
}

double PvCurve::compliance_ml_per_cmh2o(double p) const {
  const double s = 1.0 / (1.0 + std::exp(-(p - c_cmh2o) / d_cmh2o));
  return b_ml / d_cmh2o * s * (1.0 - s);
}

namespace {

// Parameters, fitted here (closed form, see below) to textbook figures of the static, deflation-limb lung
// pressure-volume curve of a 70 kg adult; the curve's form is Venegas et al. (1998).
//
// Normal. Targets: FRC 2.5 L at a transpulmonary pressure of +5 cmH2O (intrapleural -5 cmH2O at FRC, West,
// Respiratory Physiology: The Essentials, ch. 7), TLC 6.0 L at 30 cmH2O, lung compliance at FRC about
// 200 mL/cmH2O (West, ch. 7). With a = 1.0 L, the three targets give b = 5.1 L, d = 5.3 cmH2O and c = 9.6 cmH2O:
// FRC lies below the inflection point, on the steep part, where quiet breathing happens.
//   => V(5) = 2.51 L, V(30) = 5.99 L, C(5) = 200 mL/cmH2O.
//
// Emphysema. Loss of elastic recoil moves the curve up and to the left and steepens it (Gibson and Pride,
// Br J Dis Chest 70:143-184, 1976; West, Pulmonary Pathophysiology, ch. 4): targets FRC 4.0 L at +3 cmH2O,
// TLC about 7.8 L, compliance at FRC about 450 mL/cmH2O.
//   => a = 2.0 L, b = 5.8 L, c = 4.9 cmH2O, d = 2.9 cmH2O; V(3) = 3.98 L, V(20) = 7.77 L, C(3) = 450 mL/cmH2O.
//
// Fibrosis. A stiff, small lung: the curve moves down and to the right and flattens (Gibson and Pride 1976):
// targets FRC 1.8 L at +8 cmH2O, TLC about 3.9 L, compliance at FRC about 90 mL/cmH2O.
//   => a = 0.7 L, b = 3.3 L, c = 13.6 cmH2O, d = 8.1 cmH2O; V(8) = 1.80 L, V(40) = 3.88 L, C(8) = 91 mL/cmH2O.
//
// tests/sim/breathing/pv_curve_test.cpp checks these figures from the parameters.
const PvPreset kPresets[] = {
    {Preset::Normal, {1000.0, 5100.0, 9.6, 5.3}, 5.0},
    {Preset::Emphysema, {2000.0, 5800.0, 4.9, 2.9}, 3.0},
    {Preset::Fibrosis, {700.0, 3300.0, 13.6, 8.1}, 8.0},
};

}  // namespace

const PvPreset& pv_preset(Preset preset) { return kPresets[static_cast<int>(preset)]; }

std::optional<Preset> preset_from_name(std::string_view name) { return kPresetNames.parse(name); }

std::string_view to_string(Preset preset) { return kPresetNames.name(preset); }

double max_tidal_volume_ml(const PvPreset& preset, double start_pressure_cmh2o) {
  return preset.curve.volume_ml(kMaxTranspulmonaryCmH2O) - preset.curve.volume_ml(start_pressure_cmh2o);
}

}  // namespace lungar::sim
