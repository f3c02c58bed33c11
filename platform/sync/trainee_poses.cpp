/// @file trainee_poses.cpp
/// @brief The shared lung pose handed to the frame as this station's patient pose.
#include "platform/sync/trainee_poses.h"

#include <nlohmann/json.hpp>

#include "platform/runtime/gl_math.h"

namespace lungar::platform::sync {

drivers::PoseSample TraineePoses::latest(drivers::Role role, std::int64_t now_ns) const {
  if (role != drivers::Role::Patient) return own_->latest(role, now_ns);
  drivers::PoseSample shared = station_->trainee()->patient_pose();
  if (!shared.valid()) return own_->latest(role, now_ns);
  const Eigen::Isometry3d patient = pose_isometry(shared) * registration_inverse_;
  const Eigen::Quaterniond q(patient.rotation());
  shared.orientation_wxyz = {q.w(), q.x(), q.y(), q.z()};
  shared.position_mm = {patient.translation().x(), patient.translation().y(), patient.translation().z()};
  handed_.publish(shared);
  return shared;
}

drivers::PoseSample TraineePoses::predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const {
  if (role != drivers::Role::Patient) return own_->predicted(role, t_ns, max_ahead_ns);
  return latest(role, t_ns);  // the instructor's pose is shared as measured: no extrapolation across stations
}

void TraineePoses::add_stats(nlohmann::json& stats, double wall_s) const {
  own_->add_stats(stats, wall_s);
  const drivers::PoseSample handed = handed_.read();
  if (!handed.valid()) return;
  const Eigen::Quaterniond q((pose_isometry(handed) * registration_).rotation());
  stats["sync_frame_lung_orientation_wxyz"] = {q.w(), q.x(), q.y(), q.z()};
}

}  // namespace lungar::platform::sync
