/// @file classroom_breathing.cpp
/// @brief Shared or own breathing, and the sync keys of the stats JSON.
#include "drivers/breath/classroom/classroom_breathing.h"

#include <nlohmann/json.hpp>

#include "drivers/classroom/sync_report_json.h"

namespace lungar::classroom {

sim::BreathingSample ClassroomBreathing::at(std::int64_t now_ns) const {
  Trainee* trainee = station_->trainee();
  if (trainee == nullptr) return own_->at(now_ns);
  sim::BreathingSample drawn;
  if (!trainee->breathing(now_ns, drawn)) drawn = own_->at(now_ns);
  trainee->frame_breath(now_ns, drawn.t_s);  // what the frame draws is what the breath offset measures
  return drawn;
}

const sim::Pattern* ClassroomBreathing::pattern_at(std::int64_t now_ns) const {
  return station_->trainee() == nullptr ? own_->pattern_at(now_ns) : nullptr;
}

void ClassroomBreathing::add_stats(nlohmann::json& stats) const {
  own_->add_stats(stats);
  add_sync_keys(station_->report(), stats);
}

}  // namespace lungar::classroom
