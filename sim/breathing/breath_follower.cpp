/// @file breath_follower.cpp
/// @brief Turns, baseline, amplitude and the states of breath_follower.h.
#include "sim/breathing/breath_follower.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lungar::sim {

namespace {
/// A turn counts once the signal has come back by this share of the typical amplitude.
constexpr double kHysteresis = 0.3;
}  // namespace

void BreathFollower::add(double t_s, double value) {
  if (!std::isfinite(t_s) || !std::isfinite(value) || (any_ && t_s < last_t_)) {
    ++dropped_;
    return;
  }
  if (!any_) {
    any_ = true;
    extreme_ = {t_s, value};
    lo_ = hi_ = value;
    last_t_ = t_s;
    last_value_ = value;
    return;
  }
  if (t_s - last_t_ > p_.lost_after_s) {  // back after a loss: calibrate again, and count an apnoea from now
    breaths_at_return_ = breaths_;
    returned_s_ = t_s;
  }
  lo_ = std::min(lo_, value);
  hi_ = std::max(hi_, value);
  const double h = kHysteresis * (amplitudes_.count == 0 ? hi_ - lo_ : amplitude());
  if (rising_) {
    if (value > extreme_.value) {
      extreme_ = {t_s, value};
    } else if (h > 0 && extreme_.value - value > h) {
      turn_found(false, extreme_);
      rising_ = false;
      extreme_ = {t_s, value};
    }
  } else {
    if (value < extreme_.value) {
      extreme_ = {t_s, value};
    } else if (h > 0 && value - extreme_.value > h) {
      turn_found(true, extreme_);
      rising_ = true;
      extreme_ = {t_s, value};
    }
  }
  last_t_ = t_s;
  last_value_ = value;
  bin(t_s, value);
  newest_[newest_next_] = {t_s, value};
  newest_next_ = (newest_next_ + 1) % newest_.size();
  newest_count_ = std::min(newest_count_ + 1, newest_.size());
}

double BreathFollower::predicted(double t_s) const {
  // Least squares slope over the samples of the last kSlopeWindowS: noise averages out, a turn bends it little.
  double st = 0, sv = 0, stt = 0, stv = 0;
  int n = 0;
  for (std::size_t i = 0; i < newest_count_; ++i) {
    const Turn& s = newest_[(newest_next_ + newest_.size() - 1 - i) % newest_.size()];
    if (last_t_ - s.t_s > kSlopeWindowS) break;
    const double t = s.t_s - last_t_;
    st += t, sv += s.value, stt += t * t, stv += t * s.value;
    ++n;
  }
  const double det = n * stt - st * st;
  if (n < 3 || !(det > 0)) return last_value_;
  const double slope = (n * stv - st * sv) / det;
  const double ahead = std::clamp(t_s - last_t_, 0.0, kMaxPredictS);
  // Within the breath: no deeper than the deepest of the last breaths, no lower than the end-exhale level, so that
  // the turn at a peak or a trough, where a straight line overshoots, stays where the breaths turned.
  const double deepest = *std::max_element(amplitudes_.v.begin(), amplitudes_.v.begin() + amplitudes_.count);
  const double base = baseline(), top = base + deepest;
  return std::clamp(last_value_ + slope * ahead, std::min(base, last_value_), std::max(top, last_value_));
}

void BreathFollower::turn_found(bool trough, const Turn& t) {
  if (trough) {
    // The end-exhale of the coming breath: the lowest point since the last breath (talking's small troughs
    // between two breaths are not it).
    if (!has_low_ || t.value < low_.value) low_ = t;
    has_low_ = true;
    return;
  }
  if (!has_low_) return;  // a peak before any trough: no breath to measure yet
  // Too soon after the last turn of any kind: talking turns three times a second, and every one of its turns
  // counts, so that a stretch of it never passes for a breath every min_breath_s.
  const bool too_soon = last_turn_s_ >= 0 && t.t_s - last_turn_s_ < p_.min_breath_s;
  last_turn_s_ = t.t_s;
  const double a = t.value - low_.value;
  if (!(a > 0)) return;
  const bool too_shallow = amplitudes_.count > 0 && a < p_.min_depth_share * amplitude();
  if (too_soon || too_shallow) {  // the chest moved, but not a breath: followed, flagged, not learnt from
    irregular_breaths_ += irregular_ ? 0 : 1;
    irregular_ = true;
    return;
  }
  irregular_ = irregular(a, t.t_s);
  irregular_breaths_ += irregular_ ? 1 : 0;
  amplitudes_.push(a);
  peak_times_.push(t.t_s);
  // Bounded slope: the level moves by at most one typical depth a breath, so that a cough's or a shift's deep
  // exhale (five depths below, in a real recording) does not drag it; a real step is reached over a few breaths.
  const double level = baseline(), reach = amplitudes_.count > 0 ? amplitude() : a;
  end_exhales_.push(end_exhales_.count > 0 ? std::clamp(low_.value, level - reach, level + reach) : low_.value);
  has_low_ = false;
  ++breaths_;
}

bool BreathFollower::irregular(double a, double t_s) const {
  const double share = p_.irregular_share;
  if (amplitudes_.count >= 3 && std::abs(a / amplitude() - 1.0) > share) return true;
  const std::size_t n = peak_times_.count;
  if (n < 3) return false;
  std::array<double, kMaxMedianOf> periods{};
  for (std::size_t i = 1; i < n; ++i) periods[i - 1] = peak_times_.v[i] - peak_times_.v[i - 1];
  const auto mid = periods.begin() + static_cast<std::ptrdiff_t>((n - 1) / 2);
  std::nth_element(periods.begin(), mid, periods.begin() + static_cast<std::ptrdiff_t>(n - 1));
  const double period = t_s - peak_times_.v[n - 1];
  return *mid > 0 && std::abs(period / *mid - 1.0) > share;
}

double BreathFollower::amplitude() const {
  std::array<double, kMaxMedianOf> a = amplitudes_.v;
  const std::size_t n = amplitudes_.count;
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(n / 2),
                   a.begin() + static_cast<std::ptrdiff_t>(n));
  return a[n / 2];
}

double BreathFollower::rate_per_min() const {
  const std::size_t n = peak_times_.count;
  if (n < 2) return 0;
  const double span = peak_times_.v[n - 1] - peak_times_.v[0];
  return span > 0 ? 60.0 * static_cast<double>(n - 1) / span : 0.0;
}

void BreathFollower::bin(double t_s, double value) {
  const long index = static_cast<long>(std::floor(t_s / kLevelBinS));
  if (index != bin_index_ && bin_n_ > 0) {  // bins a loss skipped stay unfilled: the window is of what was seen
    bins_[bins_next_] = bin_sum_ / bin_n_;
    bins_next_ = (bins_next_ + 1) % kLevelBins;
    bins_count_ = std::min(bins_count_ + 1, kLevelBins);
    bin_sum_ = 0;
    bin_n_ = 0;
  }
  bin_index_ = index;
  bin_sum_ += value;
  ++bin_n_;
}

double BreathFollower::window_level() const {
  if (bins_count_ < 16) return std::nan("");
  std::array<double, kLevelBins> b = bins_;
  const auto n = static_cast<std::ptrdiff_t>(bins_count_);
  const auto q = static_cast<std::ptrdiff_t>(kLevelQuantile * static_cast<double>(n - 1) + 0.5);
  std::nth_element(b.begin(), b.begin() + q, b.begin() + n);
  return b[static_cast<std::size_t>(q)];
}

double BreathFollower::baseline() const {
  if (end_exhales_.count == 0) return has_low_ ? low_.value : lo_;
  std::array<double, kMaxMedianOf> e = end_exhales_.v;
  const std::size_t n = end_exhales_.count;
  std::sort(e.begin(), e.begin() + static_cast<std::ptrdiff_t>(n));
  const double med = n % 2 == 1 ? e[n / 2] : 0.5 * (e[n / 2 - 1] + e[n / 2]);
  // A quiet breath's end-exhale lies inside the band (a sinusoidal one's, a quarter of a depth below the window's
  // level; one with an end-expiratory pause, closer): the band acts only when the chest has settled elsewhere.
  // A volume source's end-exhale is its own.
  const double w = window_level();
  if (p_.in_ml || !std::isfinite(w) || amplitudes_.count == 0) return med;
  return std::clamp(med, w - kLevelBelow * amplitude(), w);
}

double BreathFollower::depth_ml() const {
  if (amplitudes_.count == 0) return 0.0;
  return p_.in_ml ? amplitude() : p_.tidal_volume_ml;
}

double BreathFollower::max_ml() const { return p_.max_ml > 0 ? p_.max_ml : 3.0 * p_.tidal_volume_ml; }

double BreathFollower::bounded(double raw_ml) const {
  const double vt = p_.tidal_volume_ml, top = max_ml();
  const double floor_soft = -vt / 4, floor_span = vt / 4;   // compressed from -V_T/4 towards -V_T/2
  const double top_span = std::min(vt, 0.5 * top), top_soft = top - top_span;  // towards max_ml
  if (raw_ml < floor_soft) return floor_soft - floor_span * std::tanh((floor_soft - raw_ml) / floor_span);
  if (raw_ml > top_soft) return top_soft + top_span * std::tanh((raw_ml - top_soft) / top_span);
  return raw_ml;
}

FollowerOutput BreathFollower::at(double t_s, double model_dv_ml) {
  const bool lost = !any_ || t_s - last_t_ > p_.lost_after_s;
  const bool calibrated = breaths_ >= p_.calibration_breaths && amplitudes_.count > 0 &&
                          (breaths_at_return_ < 0 || breaths_ - breaths_at_return_ >= 1);
  double target = model_dv_ml, k = 0, seen_value = last_value_;
  bool was_bounded = false;
  const bool was_following = state_ == BreathState::Following;
  if (lost) {
    const bool recently = any_ && t_s - last_t_ - p_.lost_after_s < p_.holding_s;
    state_ = recently && state_ != BreathState::Model ? BreathState::Holding : BreathState::Model;
  } else if (calibrated) {
    state_ = BreathState::Following;
    k = p_.in_ml ? 1.0 : p_.tidal_volume_ml / amplitude();
    seen_value = p_.predict ? predicted(t_s + p_.predict_s) : last_value_;
    const double raw = k * (seen_value - baseline());
    was_bounded = !p_.in_ml && (raw < -p_.tidal_volume_ml / 2 || raw > max_ml());
    target = p_.in_ml ? raw : bounded(raw);
    bounded_ += was_bounded ? 1 : 0;
  } else {
    state_ = BreathState::Model;
  }
  // No jump: once dV is on its source, it moves as the source itself moved this step (the signal's own change at
  // the current scale, or the model's), so steady following has no lag; anything else (a change of source, a
  // new end-exhale level or scale) is caught up at no more than kHandoverMlPerS.
  const bool following = state_ == BreathState::Following;
  if (!out_started_) {
    out_ml_ = target;
    out_started_ = true;
  } else {
    double limit = kHandoverMlPerS * std::max(0.0, t_s - out_t_);
    if (caught_up_ && following == was_following)
      limit =
          std::max(limit, following ? std::abs(k * (seen_value - used_value_)) : std::abs(model_dv_ml - used_model_));
    out_ml_ += std::clamp(target - out_ml_, -limit, limit);
  }
  caught_up_ = std::abs(target - out_ml_) < 1e-9;
  out_t_ = t_s;
  used_value_ = seen_value;
  used_model_ = model_dv_ml;
  // Apnoea: the signal is there (not lost) and has made no breath for apnoea_s since the last one it made (or
  // since it came back after a loss: what happened in the gap is not known).
  // Talking counts as the chest moving: its turns end an apnoea as a breath does.
  const bool apnoea = !lost && breaths_ > 0 && t_s - std::max(last_turn_s_, returned_s_) > p_.apnoea_s;
  apnoeas_ += apnoea && !in_apnoea_ ? 1 : 0;
  in_apnoea_ = apnoea;
  return {out_ml_, state_, last_value_, apnoea, irregular_ && !apnoea, was_bounded};
}

}  // namespace lungar::sim
