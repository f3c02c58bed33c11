/// @file frame_stats.h
/// @brief What the frame loop measures: frame times, pose ages, volumes; summarised as the stats JSON and a line.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lungar::platform {

/// Counters that come from the tracker side at the end of a run.
struct TrackerCounters {
  std::uint64_t reports = 0;
  std::uint64_t malformed = 0;
  std::uint64_t reconnects = 0;
  double rate_hz = 0;
  std::string state;
};

class FrameStats {
 public:
  /// Reserves room for `expected_frames` so that recording a frame does not allocate in the loop.
  explicit FrameStats(std::size_t expected_frames = 4096);

  /// One frame: its duration (previous submit -> this submit), the age of the patient pose it used (report
  /// arrival -> frame submitted; negative when there was no pose), and the lung volume change drawn.
  void record(double frame_ms, double pose_age_ms, double volume_ml);

  std::size_t frames() const { return frame_ms_.size(); }

  /// Median, p-th percentile (0..100, nearest rank on a sorted copy).
  static double percentile(std::vector<double> values, double p);

  /// The stats JSON (DESIGN.md keys: snake_case, unit suffix). `extra` is merged in (a JSON object text).
  std::string to_json(const std::string& view, const std::string& deform, std::uint64_t nodes,
                      const TrackerCounters& tracker, double wall_s) const;
  /// One human line for the console.
  std::string summary(const TrackerCounters& tracker) const;

 private:
  std::vector<double> frame_ms_;
  std::vector<double> pose_age_ms_;
  double volume_min_ = 0, volume_max_ = 0;
  bool any_volume_ = false;
};

}  // namespace lungar::platform
