/// @file pose_source.cpp
/// @brief The tracker_* keys every source writes the same way.
#include "platform/runtime/pose_source.h"

#include <nlohmann/json.hpp>

namespace lungar::platform {

void PoseSource::add_stats(nlohmann::json& stats, double wall_s) const {
  const SourceCounters c = counters(wall_s);
  stats["tracker_reports"] = c.reports;
  stats["tracker_malformed"] = c.malformed;
  stats["tracker_reconnects"] = c.reconnects;
  stats["tracker_rate_hz"] = c.rate_hz;
  stats["tracker_state"] = c.state;
}

}  // namespace lungar::platform
