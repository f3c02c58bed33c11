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
  /// Adds the clock's keys to the stats JSON.
  virtual void add_stats(nlohmann::json& stats) const { (void)stats; }
};

}  // namespace lungar::breath
