/// @file breathing_clock.h
/// @brief Where the frame's breathing comes from: this station's own breathing script run from its start, a
/// followed surrogate (a trace, a live marker, a mannequin or a ventilator), or a classroom's shared time base. The
/// frame asks for the state at a time and never knows which clock answers.
/// @ingroup breath
#pragma once

#include <cstdint>

#include <nlohmann/json_fwd.hpp>

#include "sim/breathing/driver.h"

namespace lungar::breath {

class BreathingClock {
 public:
  virtual ~BreathingClock() = default;
  /// The breathing state (P, V, dV, phase) at monotonic time `now_ns`. Allocates nothing.
  virtual sim::BreathingSample at(std::int64_t now_ns) const = 0;
  /// The modelled pattern in force at `now_ns` (rate, tidal volume, mode, a hold or an apnoea), for the status line
  /// and the log; null when the breath comes from elsewhere (an instructor's). Allocates nothing.
  virtual const sim::Pattern* pattern_at(std::int64_t now_ns) const {
    (void)now_ns;
    return nullptr;
  }
  /// Adds the clock's keys to the stats JSON.
  virtual void add_stats(nlohmann::json& stats) const { (void)stats; }
};

}  // namespace lungar::breath
