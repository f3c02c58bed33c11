/// @file followed_breathing.cpp
/// @brief The follower behind the BreathingClock interface (followed_breathing.h).
#include "drivers/breath/source/followed_breathing.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "config/base/log_line.h"
#include "sim/breathing/pv_curve.h"

namespace lungar::breath {

FollowedBreathing::FollowedBreathing(std::shared_ptr<SurrogateFeed> feed,
                                     std::shared_ptr<const sim::BreathingScript> model, std::int64_t t0_ns)
    : feed_(std::move(feed)), model_(std::move(model)), t0_ns_(t0_ns) {
  sim::FollowerParams p;
  p.tidal_volume_ml = model_->start.tidal_volume_ml;
  // Each frame's sample age is measured (the frame's time against the newest sample's); beyond it, the frame
  // reaches the eye about one refresh of a 60 Hz HMD later.
  p.predict_s = kFrameToPhotonsS;
  p.in_ml = feed_->in_ml();
  // The highest the lungs can go above the end-exhale level: the preset's inspiratory capacity (TLC - FRC).
  const sim::PvPreset& preset = sim::pv_preset(model_->start.preset);
  p.max_ml = std::min(3.0 * p.tidal_volume_ml, sim::max_tidal_volume_ml(preset, preset.p_frc_cmh2o));
  followers_.breath = sim::BreathFollower(p);
  followers_.lungs = {sim::BreathFollower(p), sim::BreathFollower(p)};
}

sim::BreathingSample FollowedBreathing::at(std::int64_t now_ns) const {
  const double t = seconds_between(t0_ns_, now_ns);
  feed_->feed(t, followers_);
  sim::BreathingSample s = model_->driver.at(t);
  const sim::FollowerOutput o = followers_.breath.at(t, s.dv_ml);
  if (feed_->per_lung()) {
    for (std::size_t l = 0; l < 2; ++l) {  // a lung followed on its own; else its posture's share of the breath
      const sim::FollowerOutput lung = followers_.lungs[l].at(t, 0.5 * s.dv_ml);
      if (lung.state == sim::BreathState::Following) s.lung_dv_ml[l] = lung.dv_ml;
    }
  }
  if (o.state == sim::BreathState::Following) {
    lag_sum_s_ += t - followers_.breath.last_sample_s();
    ++lag_n_;
    following_s_ += std::max(0.0, t - last_t_);
  }
  last_t_ = t;
  state_ = o.state;
  if (o.apnoea && !apnoea_) {  // rare: one line when it starts, for the trainer
    char line[128];
    std::snprintf(line, sizeof line, "breath: apnoea: no breath for %.0f s at t = %.1f s",
                  sim::FollowerParams{}.apnoea_s, t);
    log_line("lungar", line);
  }
  apnoea_ = o.apnoea;
  s.dv_ml = o.dv_ml;
  s.v_ml = s.v_frc_ml + o.dv_ml;
  return s;
}

void FollowedBreathing::add_stats(nlohmann::json& stats) const {
  feed_->add_stats(stats);
  stats["breath_state"] = sim::kBreathStateNames.name(state_);
  stats["breath_rate_per_min"] = followers_.breath.rate_per_min();
  stats["breath_lag_ms"] = lag_n_ > 0 ? 1000.0 * lag_sum_s_ / static_cast<double>(lag_n_) : 0.0;
  stats["breath_following_s"] = following_s_;
  stats["breath_apnoeas"] = followers_.breath.apnoeas();
  stats["breath_irregular"] = followers_.breath.irregular_breaths();
  stats["breath_bounded_samples"] = followers_.breath.bounded_samples();
  stats["breath_max_ml"] = followers_.breath.max_ml();
  stats["breath_depth_ml"] = followers_.breath.depth_ml();
}

}  // namespace lungar::breath
