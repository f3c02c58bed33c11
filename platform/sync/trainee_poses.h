/// @file trainee_poses.h
/// @brief A trainee's PoseSource: its head from its own tracker, the patient from the classroom's instructor.
/// @ingroup platform
///
/// The instructor shares the lung frame in the world (its patient pose after its registration). The frame
/// applies this station's registration to whatever patient pose it reads, so the shared lung pose is handed
/// over as the patient pose that this registration turns back into it: patient = lung * registration^-1.
/// Until the instructor has spoken, the station's own patient pose stands in.
#pragma once

#include <memory>

#include <Eigen/Geometry>

#include "drivers/classroom/classroom_station.h"
#include "drivers/pose/mailbox.h"
#include "platform/runtime/pose_source.h"

namespace lungar::platform::sync {

class TraineePoses final : public PoseSource {
 public:
  TraineePoses(std::unique_ptr<PoseSource> own, std::shared_ptr<classroom::ClassroomStation> station,
               const Eigen::Isometry3d& registration)
      : own_(std::move(own)),
        station_(std::move(station)),
        registration_(registration),
        registration_inverse_(registration.inverse()) {}

  std::string describe() const override { return own_->describe() + ", patient shared by the classroom's instructor"; }
  drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const override;
  drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const override;
  /// "sync lost" while the instructor is silent, else the own tracker's state.
  const char* state() const override { return station_->lost() ? "sync lost" : own_->state(); }
  bool finished() const override { return own_->finished(); }
  SourceCounters counters(double wall_s) const override { return own_->counters(wall_s); }
  /// The own tracker's keys, and sync_frame_lung_orientation_wxyz: the lung orientation the frame made of the
  /// last patient pose it read here (through this station's registration, as the frame does): what it drew.
  void add_stats(nlohmann::json& stats, double wall_s) const override;
  void stop() override { own_->stop(); }

 private:
  std::unique_ptr<PoseSource> own_;
  std::shared_ptr<classroom::ClassroomStation> station_;
  Eigen::Isometry3d registration_, registration_inverse_;
  mutable drivers::LatestMailbox<drivers::PoseSample> handed_;  ///< the last patient pose handed to the frame
};

}  // namespace lungar::platform::sync
