/// @file event.h
/// @brief Timed changes to breathing: new parameters, a sigh, breath holds and apnoeas, ventilator on or off.
#pragma once

#include <optional>

#include "sim/breathing/pattern.h"
#include "sim/breathing/pv_curve.h"

namespace lungar::sim {

/// Parameters to change; those left empty keep their value.
struct PatternChange {
  std::optional<Preset> preset;
  std::optional<double> rate_bpm;
  std::optional<double> ie_ratio;
  std::optional<double> tidal_volume_ml;
  std::optional<Mode> mode;                 ///< Ventilator: square pressure wave; Spontaneous: back to normal
  std::optional<double> ventilator_tau_s;
  std::optional<double> peep_cmh2o;
};

enum class EventKind {
  Change,       ///< new parameters (PatternChange)
  Sigh,         ///< the next breath is deeper (sigh_volume_ml)
  HoldStart,    ///< breath hold: the cycle stops where it is
  HoldEnd,      ///< the cycle goes on from where it stopped
  ApnoeaStart,  ///< breathing fades out to the end-expiratory volume
  ApnoeaEnd,    ///< breathing fades back in
};

/// `transition_s` < 0 lets the driver choose (driver.h); a shorter one than continuity allows is lengthened.
struct Event {
  double t_s = 0;
  EventKind kind = EventKind::Change;
  PatternChange change;
  double sigh_volume_ml = 0;  ///< Sigh: the sigh's tidal volume; 0: twice the current target
  double transition_s = -1;

  static Event set(double t_s, PatternChange change, double transition_s = -1) {
    return {t_s, EventKind::Change, change, 0, transition_s};
  }
  static Event of(double t_s, EventKind kind) { return {t_s, kind, {}, 0, -1}; }
  static Event sigh(double t_s, double volume_ml = 0) { return {t_s, EventKind::Sigh, {}, volume_ml, -1}; }
};

const char* to_string(EventKind kind);

}  // namespace lungar::sim
