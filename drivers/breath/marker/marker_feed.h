/// @file marker_feed.h
/// @brief `--breath marker:ROLE`: a marker on the chest or abdomen, tracked live as one of the tracker's roles (a
///        HID sensor, an OpenIGTLink device, a replayed log), as the breath follower's surrogate. Its positions are
///        taken in the patient's frame (so that turning the patient is not breathing), and reduced to their
///        excursion along the marker's main breathing axis, which it finds by itself over its first
///        kMarkerAxisWindowS (breathing_axis(): the principal axis, inhalation the shorter phase).
/// @ingroup breath
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "config/base/breath_source_names.h"
#include "config/base/result.h"
#include "config/base/spsc_ring.h"
#include "drivers/breath/source/surrogate_feed.h"
#include "drivers/pose/pose_sample.h"

namespace lungar::breath {

/// The marker's breathing axis is found over this much of its first samples (two or three quiet breaths).
inline constexpr double kMarkerAxisWindowS = 10.0;

class MarkerFeed final : public SurrogateFeed {
 public:
  /// Follows `role`'s samples; times are seconds from `t0_ns` (the run's start, monotonic).
  MarkerFeed(drivers::Role role, std::int64_t t0_ns);

  /// The tracker thread, for every accepted sample (TrackerOptions::on_sample): the patient's newest pose is kept,
  /// the marker's position goes into a single-producer ring in the patient's frame. Never blocks or allocates.
  void push(const drivers::PoseSample& s);

  /// The frame thread: until the axis is known the samples are kept (up to the window's worth); then each goes to
  /// the follower as its excursion along the axis.
  void feed(double t_s, Followers& followers) override;
  void add_stats(nlohmann::json& stats) const override;
  bool axis_found() const { return axis_found_; }

 private:
  struct Sample {
    double t_s = 0;
    Eigen::Vector3d p_mm = Eigen::Vector3d::Zero();
  };
  drivers::Role role_;
  std::int64_t t0_ns_;
  // Tracker thread.
  drivers::PoseSample patient_;
  bool patient_seen_ = false;
  SpscRing<Sample, 1024> ring_;  ///< tracker thread -> frame thread; full (the frame stalled): dropped, counted
  // Frame thread.
  std::vector<double> window_t_;
  std::vector<Eigen::Vector3d> window_p_;
  bool axis_found_ = false;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ(), origin_ = Eigen::Vector3d::Zero();
  std::uint64_t samples_ = 0;
};

/// `marker:ROLE`'s feed, made before the tracker that calls its push(); or what is wrong with ROLE (the patient's
/// pose is the frame the marker is read in, so it cannot carry it).
Result<std::shared_ptr<MarkerFeed>> open_marker_feed(const std::string& source, std::int64_t t0_ns);

/// What the log says a run follows once the tracker runs: the marker, its axis window, the model until then.
std::string marker_following(const std::string& source);

}  // namespace lungar::breath
