/// @file recorded_breathing.h
/// @brief A replay's breath: the recorded frames' breathing, linear between them by session time (dV, each lung's
///        own, V, P, breathing time), the phase and breath index of the frame before.
/// @ingroup platform
#pragma once

#include <memory>

#include "drivers/breath/source/breathing_clock.h"
#include "platform/record/session_playback.h"

namespace lungar::platform::record {

class RecordedBreathing final : public breath::BreathingClock {
 public:
  explicit RecordedBreathing(std::shared_ptr<const SessionPlayback> playback) : playback_(std::move(playback)) {}
  sim::BreathingSample at(std::int64_t now_ns) const override;
  /// `breath_source`: "replay".
  void add_stats(nlohmann::json& stats) const override;

 private:
  std::shared_ptr<const SessionPlayback> playback_;
};

}  // namespace lungar::platform::record
