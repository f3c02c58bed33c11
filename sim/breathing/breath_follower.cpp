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
  const double base = baseline(last_t_), top = base + deepest;
  return std::clamp(last_value_ + slope * ahead, std::min(base, last_value_), std::max(top, last_value_));
}

void BreathFollower::turn_found(bool trough, const Turn& t) {
  if (trough) {
    if (trough_count_ == 2) troughs_[0] = troughs_[1];
    troughs_[trough_count_ == 2 ? 1 : trough_count_++] = t;
    return;
  }
  if (trough_count_ == 0) return;  // a peak before any trough: no breath to measure yet
  const double a = t.value - troughs_[trough_count_ - 1].value;
  if (!(a > 0)) return;
  irregular_ = irregular(a, t.t_s);
  irregular_breaths_ += irregular_ ? 1 : 0;
  amplitudes_.push(a);
  peak_times_.push(t.t_s);
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

double BreathFollower::baseline(double t_s) const {
  if (trough_count_ == 0) return lo_;
  const Turn& b = troughs_[trough_count_ - 1];
  if (trough_count_ < 2) return b.value;
  const Turn& a = troughs_[0];
  const double span = b.t_s - a.t_s;
  if (!(span > 0)) return b.value;
  // The drift between the last two end-exhales, carried forward for at most one more breath.
  const double ahead = std::clamp(t_s - b.t_s, 0.0, span);
  return b.value + (b.value - a.value) / span * ahead;
}

FollowerOutput BreathFollower::at(double t_s, double model_dv_ml) {
  const bool lost = !any_ || t_s - last_t_ > p_.lost_after_s;
  const bool calibrated = breaths_ >= p_.calibration_breaths && amplitudes_.count > 0 &&
                          (breaths_at_return_ < 0 || breaths_ - breaths_at_return_ >= 2);
  double target = model_dv_ml, k = 0, seen_value = last_value_;
  const bool was_following = state_ == BreathState::Following;
  if (lost) {
    const bool recently = any_ && t_s - last_t_ - p_.lost_after_s < p_.holding_s;
    state_ = recently && state_ != BreathState::Model ? BreathState::Holding : BreathState::Model;
  } else if (calibrated) {
    state_ = BreathState::Following;
    k = p_.in_ml ? 1.0 : p_.tidal_volume_ml / amplitude();
    seen_value = p_.predict ? predicted(t_s + p_.predict_s) : last_value_;
    target = k * (seen_value - baseline(last_t_));
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
  const double last_breath_s = peak_times_.count > 0 ? peak_times_.v[peak_times_.count - 1] : 0.0;
  const bool apnoea = !lost && breaths_ > 0 && t_s - std::max(last_breath_s, returned_s_) > p_.apnoea_s;
  apnoeas_ += apnoea && !in_apnoea_ ? 1 : 0;
  in_apnoea_ = apnoea;
  return {out_ml_, state_, last_value_, apnoea, irregular_ && !apnoea};
}

}  // namespace lungar::sim
