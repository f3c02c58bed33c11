/// @file pose_prediction.cpp
/// @brief Constant linear and angular velocity extrapolation.
#include "platform/runtime/pose_prediction.h"

#include <algorithm>

namespace lungar::platform {

TimedPose predict_pose(const TimedPose& older, const TimedPose& newer, std::int64_t t_target_ns, double max_ahead_ms) {
  const double span_s = static_cast<double>(newer.t_ns - older.t_ns) * 1e-9;
  if (span_s <= 0) return newer;
  const double ahead_s = std::clamp(static_cast<double>(t_target_ns - newer.t_ns) * 1e-9, 0.0, max_ahead_ms * 1e-3);
  TimedPose out = newer;
  out.t_ns = newer.t_ns + static_cast<std::int64_t>(ahead_s * 1e9);
  out.position_mm = newer.position_mm + (newer.position_mm - older.position_mm) * (ahead_s / span_s);
  // The rotation from older to newer, in the world frame, scaled in angle by ahead/span.
  Eigen::Quaterniond delta = newer.orientation * older.orientation.conjugate();
  if (delta.w() < 0) delta.coeffs() = -delta.coeffs();  // the short way round
  Eigen::AngleAxisd step(delta);
  step.angle() *= ahead_s / span_s;
  out.orientation = (Eigen::Quaterniond(step) * newer.orientation).normalized();
  return out;
}

}  // namespace lungar::platform
