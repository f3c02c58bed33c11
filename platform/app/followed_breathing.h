/// @file followed_breathing.h
/// @brief The frame's breathing from the patient's own respiratory surrogate (`lungar --breath FILE`,
///        `--breath marker:ROLE`, `amm`, `openice`): its samples fed to the breath follower as the run's clock reaches them, the
///        breathing script's model behind it for the handovers (before calibration, while the signal is lost, after
///        a trace ends).
/// @ingroup platform
#pragma once

#include <array>
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

/// The followers a feed gives its samples to: the whole breath's, and each lung's own (left, right) when the
/// source measures each lung.
struct Followers {
  sim::BreathFollower breath;
  std::array<sim::BreathFollower, 2> lungs;
};

/// Where a followed breath's samples come from: a recorded trace, a live marker (marker_feed.h), a mannequin or a
/// ventilator over DDS (physiology_feed.h).
class SurrogateFeed {
 public:
  virtual ~SurrogateFeed() = default;
  /// Gives the followers the samples taken up to `t_s` (seconds from the run's start). The frame thread;
  /// allocates nothing.
  virtual void feed(double t_s, Followers& followers) = 0;
  /// breath_source and what names it, breath_invalid_samples.
  virtual void add_stats(nlohmann::json& stats) const = 0;
  /// Whether the samples are volumes in mL (FollowerParams::in_ml), not a surrogate to scale to V_T.
  virtual bool in_ml() const { return false; }
  /// Whether it feeds Followers::lungs too.
  virtual bool per_lung() const { return false; }
};

/// A recorded trace (CSV, .vxp), its samples at their own times from the run's start.
class TraceFeed final : public SurrogateFeed {
 public:
  TraceFeed(sim::BreathTrace trace, std::string path) : trace_(std::move(trace)), path_(std::move(path)) {}
  void feed(double t_s, Followers& followers) override;
  void add_stats(nlohmann::json& stats) const override;

 private:
  sim::BreathTrace trace_;
  std::string path_;
  std::size_t next_ = 0;
};

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

}  // namespace lungar::platform
