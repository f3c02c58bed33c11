/// @file frame_stats.h
/// @brief What the frame loop measures: frame times, pose ages, volumes; in constant memory (log histograms), so
/// a teaching day at display rate does not grow the process.
/// @ingroup platform
#pragma once

#include <array>
#include <optional>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/base/log_histogram.h"

namespace lungar::platform {

/// Lungs followed one by one in the stats: as many as the renderer draws (render::kMaxLungs).
inline constexpr std::size_t kMaxStatsLungs = 8;

class FrameStats {
 public:
  /// One frame: its duration (previous submit -> this submit), the age of the head pose it used (report arrival
  /// -> frame submitted; negative when there was no pose), the lung volume change drawn, and the direction of
  /// gravity in the lung frame (LPS: upright is -z, supine +y). Allocates nothing.
  void record(double frame_ms, double pose_age_ms, double volume_ml, const std::array<double, 3>& gravity_lung);

  /// The lungs' names, in the asset's order, for the per-lung keys (at most kMaxStatsLungs are followed).
  void name_lungs(const std::vector<std::string>& names);
  /// Each lung's own volume change this frame, mL (its share of the breath in the posture), and its rest volume
  /// (a pneumothorax shrinks it while the lungs are drawn), in name_lungs' order.
  void record_lungs(std::span<const double> lung_volume_ml, std::span<const double> rest_volume_ml);
  /// The anterior half's share of a breath in this frame's posture (sim/motion/ventral_share.h).
  void record_ventral_share(double share) { ventral_share_ = share; }

  std::uint64_t frames() const { return frame_ms_.count(); }
  const LogHistogram& frame_ms() const { return frame_ms_; }
  const LogHistogram& pose_age_ms() const { return pose_age_ms_; }

  /// The frame keys of the stats JSON (docs/design.md, Contracts: snake_case, unit suffix): frames, fps_median, frame_ms_p50,
  /// frame_ms_p99, frame_ms_mean, pose_age_ms_p50, pose_age_ms_p99, volume_ml_min, volume_ml_max, and gravity_lung_first,
  /// gravity_lung_last (unit vectors: how the patient lay at the first and the last frame), and per_lung: one
  /// {name, tidal_ml, volume_ml_min, volume_ml_max, rest_volume_ml} a lung, tidal_ml its swing over the run
  /// (max - min), rest_volume_ml its rest volume at the last frame; and
  /// ventral_share: the part of a breath the anterior half of the lungs sweeps, in the last frame's posture.
  nlohmann::ordered_json to_json() const;
  /// "N frames, F fps median (p50 .. ms, p99 .. ms); pose age p50 .. ms; dV a..b mL".
  std::string summary() const;

 private:
  LogHistogram frame_ms_, pose_age_ms_;
  double volume_min_ = 0, volume_max_ = 0;
  bool any_volume_ = false;
  std::array<double, 3> gravity_first_{}, gravity_last_{};
  struct LungRange {
    std::string name;
    double min_ml = 0, max_ml = 0, rest_ml = 0;
    bool any = false;
  };
  std::array<LungRange, kMaxStatsLungs> lungs_{};
  std::size_t lung_count_ = 0;
  std::optional<double> ventral_share_;
};

}  // namespace lungar::platform
