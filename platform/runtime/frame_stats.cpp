/// @file frame_stats.cpp
/// @brief Percentiles and the stats JSON of a run.
#include "platform/runtime/frame_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace lungar::platform {

FrameStats::FrameStats(std::size_t expected_frames) {
  frame_ms_.reserve(expected_frames);
  pose_age_ms_.reserve(expected_frames);
}

void FrameStats::record(double frame_ms, double pose_age_ms, double volume_ml) {
  frame_ms_.push_back(frame_ms);
  if (pose_age_ms >= 0) pose_age_ms_.push_back(pose_age_ms);
  if (!any_volume_) {
    volume_min_ = volume_max_ = volume_ml;
    any_volume_ = true;
  } else {
    volume_min_ = std::min(volume_min_, volume_ml);
    volume_max_ = std::max(volume_max_, volume_ml);
  }
}

double FrameStats::percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::ceil(p / 100.0 * static_cast<double>(values.size()));
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(std::max(1.0, rank)) - 1);
  return values[index];
}

std::string FrameStats::to_json(const std::string& view, const std::string& deform, std::uint64_t nodes,
                                const TrackerCounters& tracker, double wall_s) const {
  const double p50 = percentile(frame_ms_, 50);
  nlohmann::ordered_json j;
  j["frames"] = frame_ms_.size();
  j["fps_median"] = p50 > 0 ? 1000.0 / p50 : 0.0;
  j["frame_ms_p50"] = p50;
  j["frame_ms_p99"] = percentile(frame_ms_, 99);
  j["nodes"] = nodes;
  j["view"] = view;
  j["deform"] = deform;
  j["tracker_reports"] = tracker.reports;
  j["tracker_malformed"] = tracker.malformed;
  j["tracker_reconnects"] = tracker.reconnects;
  j["tracker_rate_hz"] = tracker.rate_hz;
  j["tracker_state"] = tracker.state;
  j["pose_age_ms_p50"] = percentile(pose_age_ms_, 50);
  j["pose_age_ms_p99"] = percentile(pose_age_ms_, 99);
  j["volume_ml_min"] = volume_min_;
  j["volume_ml_max"] = volume_max_;
  j["wall_s"] = wall_s;
  return j.dump(2) + "\n";
}

std::string FrameStats::summary(const TrackerCounters& tracker) const {
  const double p50 = percentile(frame_ms_, 50);
  char line[320];
  std::snprintf(line, sizeof line,
                "%zu frames, %.1f fps median (p50 %.1f ms, p99 %.1f ms); tracker %s: %llu reports at %.1f Hz, "
                "%llu malformed, %llu reconnects; pose age p50 %.1f ms; dV %.0f..%.0f mL",
                frame_ms_.size(), p50 > 0 ? 1000.0 / p50 : 0.0, p50, percentile(frame_ms_, 99),
                tracker.state.c_str(), static_cast<unsigned long long>(tracker.reports), tracker.rate_hz,
                static_cast<unsigned long long>(tracker.malformed),
                static_cast<unsigned long long>(tracker.reconnects), percentile(pose_age_ms_, 50), volume_min_,
                volume_max_);
  return line;
}

}  // namespace lungar::platform
