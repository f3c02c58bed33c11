/// @file classroom_breathing.cpp
/// @brief Shared or own breathing, and the sync keys of the stats JSON.
#include "drivers/breath/classroom/classroom_breathing.h"

#include <nlohmann/json.hpp>

#include "drivers/classroom/sync_report_json.h"

namespace lungar::classroom {

sim::BreathingSample ClassroomBreathing::at(std::int64_t now_ns) const {
  Trainee* trainee = station_->trainee();
  sim::BreathingSample drawn;
  if (trainee == nullptr) {
    drawn = own_->at(now_ns);
  } else {
    if (!trainee->breathing(now_ns, drawn)) drawn = own_->at(now_ns);
    trainee->frame_breath(now_ns, drawn.t_s);  // what the frame draws is what the breath offset measures
  }
  last_phase_.store(drawn.phase, std::memory_order_relaxed);
  return drawn;
}

const sim::Pattern* ClassroomBreathing::pattern_at(std::int64_t now_ns) const {
  return station_->trainee() == nullptr ? own_->pattern_at(now_ns) : nullptr;
}

void ClassroomBreathing::add_stats(nlohmann::json& stats) const {
  own_->add_stats(stats);
  add_sync_keys(station_->report(), stats);
  if (last_phase_.load(std::memory_order_relaxed) == sim::BreathPhase::Hold) {
    stats["breath_state"] = "paused";
  } else if (!stats.contains("breath_state")) {
    stats["breath_state"] = "breathing";
  }
}

}  // namespace lungar::classroom
