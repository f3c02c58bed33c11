/// @file classroom_breathing.h
/// @brief The breathing clock of a classroom station: a trainee breathes on the instructor's shared time base
/// once it has it (and keeps breathing on it when the instructor goes away); before that, and on the
/// instructor or a station alone, the station's own script answers. It also writes the stats' sync_* keys.
/// @ingroup platform
#pragma once

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
  void add_stats(nlohmann::json& stats) const override;

 private:
  std::unique_ptr<breath::BreathingClock> own_;
  std::shared_ptr<ClassroomStation> station_;
};

}  // namespace lungar::classroom
