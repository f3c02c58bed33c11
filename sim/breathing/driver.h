/// @file driver.h
/// @brief The breathing driver: transpulmonary pressure P(t), volume V(t) and dV(t) = V(t) - V_FRC at any t,
///        with run-time changes that never make the volume jump.
///
/// How changes stay smooth. Time becomes a phase (breath k is phase [k, k+1)) whose speed is the breathing
/// rate; a rate change ramps that speed (smoothstep) so the phase never jumps, and a breath hold ramps it to
/// zero. Every other change (tidal volume, preset, I:E, ventilator, apnoea) cross-fades the old and new
/// patterns over a transition, both evaluated at the same phase, so P and V move continuously from the old
/// curve to the new one. The transition is at least half a breath (or the event's transition_s), and long
/// enough that the cross-fade itself adds no more than a quarter of the faster pattern's peak flow: a change
/// of preset that moves the FRC by 0.7 L
/// takes about 9 s at 12/min. A sigh only changes the next breath, which starts and ends at the FRC.
/// Where a fade would still make the volume move faster than the faster pattern's peak flow (when the fade's
/// own drift meets a flow peak), a flow limiter, tabulated when the event is applied, holds it back and lets it
/// catch up when the flow falls; so no step is larger than the largest step of steady breathing.
///
/// Use: build once, apply events in time order (e.g. a whole script at start-up), then call at(t) each frame;
/// at() allocates nothing and may be called for any t, in any order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "config/base/result.h"
#include "sim/breathing/event.h"
#include "sim/breathing/pattern.h"

namespace lungar::sim {

enum class BreathPhase { Inspiration, Expiration, Hold, Apnoea };
const char* to_string(BreathPhase phase);

struct BreathingSample {
  double t_s = 0;
  double p_cmh2o = 0;          ///< transpulmonary pressure that sets the volume
  double p_applied_cmh2o = 0;  ///< driving pressure (equals p, except on the ventilator: the square wave)
  double v_ml = 0;             ///< lung volume
  double v_frc_ml = 0;         ///< the FRC of the current curve (cross-faded during a change of preset)
  double dv_ml = 0;            ///< v_ml - v_frc_ml: what scales the deformation
  BreathPhase phase = BreathPhase::Expiration;
  std::int64_t breath = 0;     ///< index of the breath (counts from 0 at t = 0)
  /// Each lung's own dV (left, right) when the breath's source measures each lung (a mannequin's physiology
  /// engine); NaN when it does not, and each lung then takes its posture's share of dv_ml.
  std::array<double, 2> lung_dv_ml{std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::quiet_NaN()};
};

class BreathingDriver {
 public:
  /// A driver breathing `params` from t = 0, at the start of an inspiration; or why `params` are unusable.
  static Result<BreathingDriver> create(const BreathingParams& params);

  /// Applies `event` at event.t_s, which must not precede the last applied event; an error is one line saying
  /// what is wrong (then nothing changes).
  Status apply(const Event& event);

  /// The state at time t (s). Allocates nothing.
  BreathingSample at(double t_s) const;

  /// The pattern in force at time t: the one a transition under way goes to.
  const Pattern& pattern_at(double t_s) const { return segments_[segment_at(t_s)].pattern; }
  /// The parameters in force after every applied event.
  const BreathingParams& params() const { return segments_.back().pattern.params; }
  /// Time of the last applied event (0 when none).
  double last_event_s() const { return segments_.back().t0; }
  /// When the transition of the last applied event ends.
  double settled_s() const;

 private:
  /// From t0 on, the pattern is `pattern`, faded in over blend_s from what was before; the phase is
  /// phi0 + the integral of a speed ramping from f0 to f1 (breaths/s) over ramp_s.
  struct Segment {
    double t0 = 0;
    double phi0 = 0;
    double f0 = 0;
    double f1 = 0;
    double ramp_s = 0;
    double blend_t0 = 0;  ///< the fade-in starts here (earlier than t0 when the segment continues one)
    double blend_s = 0;
    std::ptrdiff_t from = -1;  ///< the segment faded out, -1: none
    Pattern pattern;
    std::vector<double> correction;  ///< flow limiter's offset on V, every kLimiterStepS from t0 (empty: none)
  };
  /// The limiter's grid, s; the share of the faster pattern's peak flow it allows; how long after a transition
  /// it may take to catch up, s.
  static constexpr double kLimiterStepS = 1e-3;
  static constexpr double kLimiterFlowShare = 0.95;
  static constexpr double kLimiterMaxTailS = 30.0;
  explicit BreathingDriver(Segment first);

  std::size_t segment_at(double t) const;
  BreathingSample raw_at(std::size_t i, double t) const;
  static double correction_at(const Segment& s, double t);
  void limit_flow(double carried, double limit, double horizon);
  static double phase_at(const Segment& s, double t);
  static double speed_at(const Segment& s, double t);
  static double blend_weight(const Segment& s, double t);
  double transition_for(const Pattern& from, const Pattern& to, double requested) const;

  std::vector<Segment> segments_;
};

}  // namespace lungar::sim
