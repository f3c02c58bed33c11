/// @file pose_prediction.h
/// @brief Constant-velocity prediction of a tracked pose to the expected display time, bounded.
///
/// The head moves while a frame is drawn; drawing the lungs for where the head will be when the frame is shown
/// keeps them locked to the patient. Linear and angular velocity come from the two newest samples.
#pragma once

#include <cstdint>

#include <Eigen/Geometry>

namespace lungar::platform {

struct TimedPose {
  std::int64_t t_ns = 0;  ///< monotonic arrival time
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// The pose at `t_target_ns`, extrapolated from `older` -> `newer` at constant velocity, with the extrapolation
/// interval clamped to [0, max_ahead_ms]. Samples that are not strictly increasing in time give `newer` unchanged.
TimedPose predict_pose(const TimedPose& older, const TimedPose& newer, std::int64_t t_target_ns, double max_ahead_ms);

}  // namespace lungar::platform
