/// @file frame_stats.cpp
/// @brief The frame keys of the stats JSON and the console line.
#include "platform/runtime/frame_stats.h"

#include <algorithm>
#include <cstdio>

namespace lungar::platform {

void FrameStats::record(double frame_ms, double pose_age_ms, double volume_ml,
                        const std::array<double, 3>& gravity_lung) {
  if (frame_ms_.count() == 0) gravity_first_ = gravity_lung;
  gravity_last_ = gravity_lung;
  frame_ms_.add(frame_ms);
  if (pose_age_ms >= 0) pose_age_ms_.add(pose_age_ms);
  volume_min_ = any_volume_ ? std::min(volume_min_, volume_ml) : volume_ml;
  volume_max_ = any_volume_ ? std::max(volume_max_, volume_ml) : volume_ml;
  any_volume_ = true;
}

void FrameStats::name_lungs(const std::vector<std::string>& names) {
  lung_count_ = std::min(names.size(), kMaxStatsLungs);
  for (std::size_t l = 0; l < lung_count_; ++l) lungs_[l] = {names[l], 0, 0, false};
}

void FrameStats::record_lungs(std::span<const double> lung_volume_ml, std::span<const double> rest_volume_ml) {
  for (std::size_t l = 0; l < std::min({lung_volume_ml.size(), rest_volume_ml.size(), lung_count_}); ++l) {
    LungRange& r = lungs_[l];
    const double v = lung_volume_ml[l];
    r.rest_ml = rest_volume_ml[l];
    r.min_ml = r.any ? std::min(r.min_ml, v) : v;
    r.max_ml = r.any ? std::max(r.max_ml, v) : v;
    r.any = true;
  }
}

nlohmann::ordered_json FrameStats::to_json() const {
  const double p50 = frame_ms_.percentile(50);
  nlohmann::ordered_json j;
  j["frames"] = frame_ms_.count();
  j["fps_median"] = p50 > 0 ? 1000.0 / p50 : 0.0;
  j["frame_ms_p50"] = p50;
  j["frame_ms_p99"] = frame_ms_.percentile(99);
  j["frame_ms_mean"] = frame_ms_.mean();
  j["pose_age_ms_p50"] = pose_age_ms_.percentile(50);
  j["pose_age_ms_p99"] = pose_age_ms_.percentile(99);
  j["volume_ml_min"] = volume_min_;
  j["volume_ml_max"] = volume_max_;
  j["gravity_lung_first"] = gravity_first_;
  j["gravity_lung_last"] = gravity_last_;
  if (lung_count_ > 0) {
    nlohmann::ordered_json lungs = nlohmann::ordered_json::array();
    for (std::size_t l = 0; l < lung_count_; ++l) {
      const LungRange& r = lungs_[l];
      lungs.push_back({{"name", r.name},
                       {"tidal_ml", r.max_ml - r.min_ml},
                       {"volume_ml_min", r.min_ml},
                       {"volume_ml_max", r.max_ml},
                       {"rest_volume_ml", r.rest_ml}});
    }
    j["per_lung"] = lungs;
  }
  if (ventral_share_) j["ventral_share"] = *ventral_share_;
  return j;
}

std::string FrameStats::summary() const {
  const double p50 = frame_ms_.percentile(50);
  char line[200];
  std::snprintf(line, sizeof line, "%llu frames, %.1f fps median (p50 %.1f ms, p99 %.1f ms); pose age p50 %.1f ms; "
                "dV %.0f..%.0f mL", static_cast<unsigned long long>(frame_ms_.count()), p50 > 0 ? 1000.0 / p50 : 0.0,
                p50, frame_ms_.percentile(99), pose_age_ms_.percentile(50), volume_min_, volume_max_);
  return line;
}

}  // namespace lungar::platform
