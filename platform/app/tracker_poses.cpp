/// @file tracker_poses.cpp
/// @brief The tracker's counters as the stats JSON reports them.
#include "platform/app/tracker_poses.h"

namespace lungar::platform {

SourceCounters TrackerPoses::counters(double wall_s) const {
  const drivers::TrackerStats ts = tracker_->stats();
  SourceCounters c;
  c.reports = ts.reports;
  c.malformed = ts.malformed;
  c.reconnects = ts.reconnects;
  // The mean delivered rate over the run: the instantaneous rate says little once a replay has ended.
  c.rate_hz = wall_s > 0 ? static_cast<double>(ts.accepted) / wall_s : 0.0;
  c.state = drivers::to_string(ts.state);
  return c;
}

}  // namespace lungar::platform
