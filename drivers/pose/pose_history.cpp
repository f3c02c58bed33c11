/// @file pose_history.cpp
/// @brief Ring of recent poses; constant-velocity extrapolation for display-time prediction.
#include "drivers/pose/pose_history.h"

#include <algorithm>
#include <cmath>


namespace lungar::drivers {

void PoseHistory::push(const PoseSample& s) {
  ring[next] = s;
  next = static_cast<std::uint32_t>((next + 1) % kCapacity);
  if (count < kCapacity) ++count;
}

const PoseSample& PoseHistory::newest(std::size_t k) const {
  return ring[(next + kCapacity - 1 - k) % kCapacity];
}

PoseSample predict(const PoseHistory& h, std::int64_t t_ns, std::int64_t max_ahead_ns, std::int64_t baseline_ns) {
  if (h.count == 0) return PoseSample{};
  const PoseSample& a = h.newest(0);
  if (h.count < 2) return a;
  // The oldest sample within the baseline (at least the one before the newest): a longer baseline averages noise.
  std::size_t k = 1;
  while (k + 1 < h.count && a.t_device_ns - h.newest(k).t_device_ns < baseline_ns) ++k;
  const PoseSample& b = h.newest(k);
  const double dt_s = static_cast<double>(a.t_device_ns - b.t_device_ns) * 1e-9;
  const double ahead_s = static_cast<double>(std::clamp<std::int64_t>(t_ns - a.t_arrival_ns, 0, max_ahead_ns)) * 1e-9;
  if (dt_s <= 0 || ahead_s <= 0) return a;
  PoseSample out = a;
  out.set_position(a.position() + (a.position() - b.position()) / dt_s * ahead_s);
  // Angular velocity from the relative rotation b -> a (the short way), applied for the lead time in the world frame.
  const Eigen::AngleAxisd turn(a.orientation() * b.orientation().conjugate());
  if (turn.angle() > 1e-12) {
    const Eigen::AngleAxisd step(turn.angle() * (ahead_s / dt_s), turn.axis());
    out.set_orientation((Eigen::Quaterniond(step) * a.orientation()).normalized());
  }
  out.t_arrival_ns = a.t_arrival_ns + static_cast<std::int64_t>(ahead_s * 1e9);
  out.t_device_ns = a.t_device_ns + static_cast<std::int64_t>(ahead_s * 1e9);
  out.flags |= kPosePredicted;
  return out;
}

}  // namespace lungar::drivers
