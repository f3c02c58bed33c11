/// @file followed_breathing.h
/// @brief The frame's breathing from a recorded respiratory surrogate (`lungar --breath FILE`): the trace's samples
///        fed to the breath follower as the run's clock reaches them, the breathing script's model behind it for
///        the handovers (before calibration, while the signal is lost, after the trace ends).
/// @ingroup platform
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "platform/runtime/breathing_clock.h"
#include "sim/breathing/breath_follower.h"
#include "sim/breathing/breath_trace.h"
#include "sim/breathing/script.h"

namespace lungar::platform {

/// The display's share of the delay a followed breath is predicted over: one refresh at 60 Hz.
inline constexpr double kFrameToPhotonsS = 1.0 / 60.0;

class FollowedBreathing final : public BreathingClock {
 public:
  FollowedBreathing(sim::BreathTrace trace, std::string path, std::shared_ptr<const sim::BreathingScript> model,
                    std::int64_t t0_ns);
  /// The model's sample with the follower's dV. Allocates nothing.
  sim::BreathingSample at(std::int64_t now_ns) const override;
  /// breath_source, breath_file, breath_state (the last frame's), breath_rate_per_min, breath_lag_ms (the mean
  /// age of the newest sample at each followed frame: no smoothing adds to it), breath_following_s.
  void add_stats(nlohmann::json& stats) const override;

 private:
  sim::BreathTrace trace_;
  std::string path_;
  std::shared_ptr<const sim::BreathingScript> model_;
  std::int64_t t0_ns_;
  // The follower moves with the frames' clock (the frame thread alone calls at()).
  mutable sim::BreathFollower follower_;
  mutable std::size_t next_ = 0;
  mutable sim::BreathState state_ = sim::BreathState::model;
  mutable double lag_sum_s_ = 0, following_s_ = 0, last_t_ = 0;
  mutable long lag_n_ = 0;
  mutable bool apnoea_ = false;  ///< in an apnoea at the last frame: its start is logged once
};

}  // namespace lungar::platform
