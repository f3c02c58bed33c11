/// @file breath_follower.h
/// @brief Lungs that breathe with the patient: a respiratory surrogate (a chest marker's excursion, an RPM trace,
///        a belt) turned into the volume change dV that drives the deformation, causally, sample by sample, the
///        same code in the runtime and offline (`lungar-breathe --breath`).
///
/// - Breaths are found as troughs and peaks of the surrogate with hysteresis (a turn counts once the signal has
///   come back by a third of the typical amplitude), so noise and jerks make no breath.
/// - A breath counts (for the scale, the end-exhale level and the rate) only when it is one: at least
///   min_breath_s after the last one and at least min_depth_share of the typical depth. Talking, a cough, the
///   jitter of an upper-chest marker make turns that are none of these: they are followed as the chest moves and
///   flagged `irregular`, but they do not rescale the next minute or move the end-exhale level.
/// - The end-exhale level (the baseline) is the median of the last kBaselineOf breaths' end-exhales (the lowest
///   point since the breath before): a step, a drift or one deep exhale moves it by one breath's worth at most,
///   and it is never extrapolated, so a marker that shifts on the table cannot drag dV away without bound. It is
///   kept within kLevelBelow depths below the level the chest keeps coming back to (a low quantile of the last
///   8 s): talking counts no breath for many seconds while the chest settles higher or lower, and a level that
///   waited for breaths would turn that into a litre-sized dV (a real talking recording: dV pinned at its bound).
/// - Amplitude drives geometry: dV = k (s - baseline), with k = V_T / the median amplitude of the last breaths
///   (up to kMaxMedianOf, about two minutes), so a deeper breath gives a bigger dV and neither one irregular
///   breath nor a stretch of talking, whose turns can pass for deep breaths, rescales the rest; a volume source
///   (FollowerParams::in_ml) gives litres directly, k = 1.
/// - dV stays what a respiratory system can do: never more than V_T/2 below the end-exhale level (the expiratory
///   reserve a quiet breath does not reach) and never above max_ml (the inspiratory capacity). Inside
///   [-V_T/4, max_ml - V_T] dV is k (s - baseline) as it is; beyond, it is compressed smoothly towards the bound
///   (no flat top, no kink), and each sample whose raw dV lay beyond a bound is counted (bounded_samples()).
/// - States: `model` (not yet calibrated, or handed over), `following`, `holding` (the signal stopped: dV moves
///   towards the model's at most kHandoverMlPerS, no jump). After a loss it follows again once a breath of the
///   returned signal is found (the scale and the end-exhale level are kept from before), moving from the model's dV to the signal's at that same bounded rate.
/// - Prediction: dV is the surrogate extrapolated to the time it will be seen, `at()`'s time plus predict_s (the
///   display's share of the delay), from the newest sample along the slope of the last kSlopeWindowS of samples,
///   at most kMaxPredictS ahead and kept between the end-exhale level and the deepest recent breath: a sample is old by
///   the time a frame shows it (its transport, the frame's wait), and an overlay that lags the chest by 150 ms is
///   visibly behind it.
/// - Flags: `apnoea` while the signal is there but no breath has been found for apnoea_s (10 s, the clinical
///   definition of an apnoea), once the follower has seen the patient breathe; `irregular` from a breath whose
///   depth or period is off the median of the last ones by more than irregular_share (a sigh, a cough, a gasp)
///   until the next breath.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "config/base/enum_names.h"

namespace lungar::sim {

enum class BreathState { Model, Following, Holding };
inline constexpr EnumNames<BreathState, 3> kBreathStateNames{
    {{{BreathState::Model, "model"}, {BreathState::Following, "following"}, {BreathState::Holding, "holding"}}}};

/// How fast dV may move when the source changes (lost, returned): 5 mL per 10 ms step.
inline constexpr double kHandoverMlPerS = 500.0;
/// Prediction: the slope is fitted over the newest samples, and dV extrapolated along it, at most so far.
inline constexpr double kSlopeWindowS = 0.15;  ///< how much of the newest samples the slope is fitted over
inline constexpr double kMaxPredictS = 0.3;    ///< the furthest dV is extrapolated past the newest sample
/// The most breaths the amplitude's median is taken over: about two minutes, so that a stretch of talking or
/// coughing, whose turns can pass for deep breaths, cannot rescale the breath.
inline constexpr int kMaxMedianOf = 31;
/// The breaths the rate and the irregular period are taken over.
inline constexpr int kRateOf = 9;
/// The breaths whose end-exhales the end-exhale level is the median of: one odd one is outvoted.
inline constexpr int kBaselineOf = 3;
/// The level the chest keeps coming back to: a low quantile of the surrogate over its last 8 s (64 bins of
/// 125 ms). The end-exhale level stays between it and kLevelBelow typical depths below it, so that when the chest
/// settles elsewhere with no breath counted (talking shifts it for many seconds) the level goes with it.
inline constexpr double kLevelBinS = 0.125;
inline constexpr std::size_t kLevelBins = 64;
inline constexpr double kLevelQuantile = 0.35;
inline constexpr double kLevelBelow = 0.35;
struct FollowerParams {
  double tidal_volume_ml = 500.0;  ///< V_T: what the median breath of the surrogate maps to
  double lost_after_s = 0.5;       ///< no sample for this long: the signal is lost
  double holding_s = 2.0;          ///< then `holding` this long before `model`
  int calibration_breaths = 2;     ///< breaths found before following
  int median_of = kMaxMedianOf;    ///< breaths in the amplitude's median (at most kMaxMedianOf)
  double min_breath_s = 1.5;       ///< a breath peaking sooner after the last (talking, a cough) is none
  double min_depth_share = 0.3;    ///< nor one shallower than this share of the typical depth
  /// The highest dV (mL): the inspiratory capacity (TLC - FRC of the patient's preset); 0: 3 V_T.
  double max_ml = 0;
  double apnoea_s = 10.0;          ///< no breath for this long, the signal present: apnoea
  double irregular_share = 0.5;    ///< a breath's depth or period this far off the median (as a share): irregular
  double predict_s = 0.0;          ///< beyond at()'s time: the display's delay (frame to photons), s
  bool predict = true;             ///< extrapolate the newest sample to the time it is seen (false: hold it)
  /// The surrogate is itself a volume in mL (a mannequin's lung volume, a ventilator's): dV is its excursion over
  /// the end-exhale level as it is, not scaled to tidal_volume_ml.
  bool in_ml = false;
};

struct FollowerOutput {
  double dv_ml = 0;
  BreathState state = BreathState::Model;
  double surrogate = 0;    ///< the last sample's value
  bool apnoea = false;     ///< no breath for FollowerParams::apnoea_s while the signal is present
  bool irregular = false;  ///< the last breath's depth or period was off the median, or it was no breath
  bool bounded = false;    ///< dV was held inside the respiratory system's range (FollowerParams::max_ml)
};

class BreathFollower {
 public:
  explicit BreathFollower(FollowerParams p = {}) : p_(p) {
    amplitudes_.capacity = static_cast<std::size_t>(std::clamp(p_.median_of, 1, kMaxMedianOf));
    end_exhales_.capacity = kBaselineOf;
    peak_times_.capacity = kRateOf;
  }

  /// One surrogate sample (inhale up); times must not decrease. A non-finite value is dropped and counted.
  void add(double t_s, double value);
  /// dV at `t_s` (not before the last call), given the model's dV there for the handover.
  FollowerOutput at(double t_s, double model_dv_ml);

  int breaths() const { return breaths_; }
  /// Breaths a minute over the last peaks found (0 before two).
  double rate_per_min() const;
  /// The time of the last sample (s), for the sample's age.
  double last_sample_s() const { return last_t_; }
  int dropped() const { return dropped_; }
  /// Breaths flagged irregular, and apnoeas begun, so far.
  int irregular_breaths() const { return irregular_breaths_; }
  int apnoeas() const { return apnoeas_; }
  /// Outputs whose dV the bounds held (the raw dV below -V_T/2 or above max_ml).
  long bounded_samples() const { return bounded_; }
  /// The highest dV the bound allows, mL.
  double max_ml() const;
  /// The followed breath's depth in dV, mL: the median of the last breaths' depths times the scale (a volume
  /// source's own depth; a surrogate's is V_T by construction); 0 before the first breath. Sample by sample, so no
  /// frame rate changes it.
  double depth_ml() const;

 private:
  struct Turn {
    double t_s, value;
  };
  /// The last `capacity` values, oldest first; fixed storage, so that following a breath allocates nothing.
  struct Recent {
    std::array<double, kMaxMedianOf> v{};
    std::size_t count = 0, capacity = kMaxMedianOf;
    void push(double x) {
      if (count == capacity) {
        std::copy(v.begin() + 1, v.begin() + static_cast<std::ptrdiff_t>(count), v.begin());
        --count;
      }
      v[count++] = x;
    }
  };
  void turn_found(bool trough, const Turn& t);
  /// The surrogate extrapolated to `t_s` from the newest samples (their value when there is no slope to fit).
  double predicted(double t_s) const;
  /// Whether a breath of depth `a` peaking at `t_s` is off the last breaths' medians.
  bool irregular(double a, double t_s) const;
  double amplitude() const;
  double baseline() const;
  /// The kLevelQuantile of the last kLevelBins bins' means; NaN before 2 s of them.
  double window_level() const;
  /// Adds a sample to the bin of its time, closing the last bin when its time is past.
  void bin(double t_s, double value);
  /// dV within the respiratory system's range, compressed smoothly near its ends.
  double bounded(double raw_ml) const;

  FollowerParams p_;
  bool any_ = false, rising_ = true;
  double last_t_ = 0, last_value_ = 0;
  Turn extreme_{0, 0};             ///< the candidate turn: the highest point while rising, lowest while falling
  double lo_ = 0, hi_ = 0;         ///< the range seen before the first amplitude
  Turn low_{0, 0};                 ///< the lowest trough since the last breath: the next breath's end-exhale
  bool has_low_ = false;
  Recent end_exhales_;             ///< the last kBaselineOf breaths' end-exhales
  Recent amplitudes_;              ///< peak minus its end-exhale, the last median_of breaths
  Recent peak_times_;              ///< the last kMaxMedianOf breaths' peak times
  double last_turn_s_ = -1;        ///< the last peak found, breath or not: the chest moved
  std::array<Turn, 16> newest_{};  ///< the newest samples, a ring: what the slope is fitted to
  std::size_t newest_next_ = 0, newest_count_ = 0;
  std::array<double, kLevelBins> bins_{};  ///< the last kLevelBins bins' means, a ring
  std::size_t bins_next_ = 0, bins_count_ = 0;
  long bin_index_ = -1;  ///< the bin being filled: floor(t / kLevelBinS)
  double bin_sum_ = 0;
  int bin_n_ = 0;
  int breaths_ = 0, dropped_ = 0;
  bool irregular_ = false, in_apnoea_ = false;
  int irregular_breaths_ = 0, apnoeas_ = 0;
  long bounded_ = 0;
  double returned_s_ = 0;       ///< when the signal last came back after a loss
  int breaths_at_return_ = -1;  ///< breaths when the signal came back after a loss (-1: not lost)
  BreathState state_ = BreathState::Model;
  double out_ml_ = 0, out_t_ = 0;
  double used_value_ = 0, used_model_ = 0;  ///< the surrogate and the model's dV at the last at()
  bool out_started_ = false, caught_up_ = true;
};

}  // namespace lungar::sim
