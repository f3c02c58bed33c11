/// @file classroom_breathing.h
/// @brief The breathing clock of a classroom station: a trainee breathes on the instructor's shared time base
/// once it has it (and keeps breathing on it when the instructor goes away); before that, and on the
/// instructor or a station alone, the station's own script answers. It also writes the stats' sync_* keys.
/// @ingroup platform
#pragma once

#include <atomic>
#include <memory>

#include "drivers/breath/source/breathing_clock.h"
#include "drivers/classroom/classroom_station.h"

namespace lungar::classroom {

class ClassroomBreathing final : public breath::BreathingClock {
 public:
  ClassroomBreathing(std::unique_ptr<breath::BreathingClock> own, std::shared_ptr<ClassroomStation> station)
      : own_(std::move(own)), station_(std::move(station)) {}

  sim::BreathingSample at(std::int64_t now_ns) const override;
  /// The station's own pattern; null on a trainee, which draws its instructor's breath.
  const sim::Pattern* pattern_at(std::int64_t now_ns) const override;
  /// The clock's own keys, the sync_* keys, and `breath_state`: "paused" while the breath is held (an instructor's
  /// console paused it), else the source's own state, or "breathing".
  void add_stats(nlohmann::json& stats) const override;

 private:
  std::unique_ptr<breath::BreathingClock> own_;
  /// The phase of the last sample drawn (frame thread), for the stats' `breath_state`: "paused" in a breath hold.
  mutable std::atomic<sim::BreathPhase> last_phase_{sim::BreathPhase::Expiration};
  std::shared_ptr<ClassroomStation> station_;
};

}  // namespace lungar::classroom
