/// @file surrogate_feed.h
/// @brief Where a followed breath's samples come from: each source but the model (a recorded trace, a live marker,
///        a mannequin or a ventilator over DDS) is a SurrogateFeed that gives its samples to the breath followers;
///        FollowedBreathing (followed_breathing.h) turns any of them into the frame's BreathingClock.
/// @ingroup breath
#pragma once

#include <array>

#include <nlohmann/json_fwd.hpp>

#include "sim/breathing/breath_follower.h"

namespace lungar::breath {

/// The followers a feed gives its samples to: the whole breath's, and each lung's own (left, right) when the
/// source measures each lung.
struct Followers {
  sim::BreathFollower breath;
  std::array<sim::BreathFollower, 2> lungs;
};

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

}  // namespace lungar::breath
