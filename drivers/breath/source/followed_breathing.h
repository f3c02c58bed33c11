/// @file followed_breathing.h
/// @brief The frame's breathing from the patient's own respiratory surrogate (`lungar --breath FILE`,
///        `--breath marker:ROLE`, `amm`, `openice`): its samples fed to the breath follower as the run's clock
///        reaches them, the breathing script's model behind it for the handovers (before calibration, while the
///        signal is lost, after a trace ends).
/// @ingroup breath
#pragma once

#include <cstdint>
#include <memory>

#include "drivers/breath/source/breathing_clock.h"
#include "drivers/breath/source/surrogate_feed.h"
#include "sim/breathing/script.h"

namespace lungar::breath {

/// The display's share of the delay a followed breath is predicted over: one refresh at 60 Hz.
inline constexpr double kFrameToPhotonsS = 1.0 / 60.0;

class FollowedBreathing final : public BreathingClock {
 public:
  FollowedBreathing(std::shared_ptr<SurrogateFeed> feed, std::shared_ptr<const sim::BreathingScript> model,
                    std::int64_t t0_ns);
  /// The model's sample with the follower's dV. Allocates nothing.
  sim::BreathingSample at(std::int64_t now_ns) const override;
  /// The feed's keys, and breath_state (the last frame's), breath_rate_per_min, breath_lag_ms (the mean age of
  /// the newest sample at each followed frame: no smoothing adds to it), breath_following_s, breath_apnoeas,
  /// breath_irregular.
  void add_stats(nlohmann::json& stats) const override;

 private:
  std::shared_ptr<SurrogateFeed> feed_;  ///< shared: a live marker's tracker callback holds it too
  std::shared_ptr<const sim::BreathingScript> model_;
  std::int64_t t0_ns_;
  // The follower moves with the frames' clock (the frame thread alone calls at()).
  mutable Followers followers_;
  mutable sim::BreathState state_ = sim::BreathState::Model;
  mutable double lag_sum_s_ = 0, following_s_ = 0, last_t_ = 0;
  mutable long lag_n_ = 0;
  mutable bool apnoea_ = false;  ///< in an apnoea at the last frame: its start is logged once
};

}  // namespace lungar::breath
