/// @file tracker_poses.h
/// @brief The PoseSource of this station's own tracker thread (drivers/: HID, mock, replay, ...).
/// @ingroup platform
#pragma once

#include <memory>

#include "drivers/tracker/tracker.h"
#include "platform/runtime/pose_source.h"

namespace lungar::platform {

class TrackerPoses final : public PoseSource {
 public:
  explicit TrackerPoses(std::unique_ptr<drivers::Tracker> tracker) : tracker_(std::move(tracker)) {}

  std::string describe() const override { return tracker_->describe(); }
  drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const override {
    return tracker_->latest(role, now_ns);
  }
  drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const override {
    return tracker_->predicted(role, t_ns, max_ahead_ns);
  }
  const char* state() const override { return drivers::to_string(tracker_->state()); }
  bool finished() const override { return tracker_->finished(); }
  SourceCounters counters(double wall_s) const override;
  void stop() override { tracker_->stop(); }

  drivers::Tracker& tracker() { return *tracker_; }

 private:
  std::unique_ptr<drivers::Tracker> tracker_;
};

}  // namespace lungar::platform
