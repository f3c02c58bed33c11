/// @file scripted_inputs.cpp
/// @brief The bench's script.
#include "platform/bench/scripted_inputs.h"

#include <cmath>
#include <numbers>

namespace lungar::platform::bench {

namespace {
constexpr double kBreathPeriodS = 4.0;
constexpr double kTidalVolumeMl = 500.0;
constexpr double kTurnPeriodS = 20.0;
}  // namespace

Eigen::Quaterniond scripted_turn(double t_s) {
  const double turn = 0.25 * std::numbers::pi * (1.0 - std::cos(2.0 * std::numbers::pi * t_s / kTurnPeriodS));
  return Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitX()));
}

double scripted_volume_ml(double t_s) {
  return 0.5 * kTidalVolumeMl * (1.0 - std::cos(2.0 * std::numbers::pi * t_s / kBreathPeriodS));
}

drivers::PoseSample ScriptedPoses::latest(drivers::Role role, std::int64_t now_ns) const {
  drivers::PoseSample s;
  s.role = role;
  s.flags = drivers::kPoseValid;
  s.t_arrival_ns = now_ns;
  s.t_device_ns = now_ns;
  if (role == drivers::Role::Head) {
    // The head sensor looks along its +y with +z up: from the front (LPS anterior is -y) toward the lungs.
    const Eigen::Vector3d eye = centre_ - Eigen::Vector3d(0.0, kHeadDistanceMm, 0.0);
    s.set_position(eye);
    return s;
  }
  // The patient turns about the lungs' centre, so the lungs stay where the head looks.
  const Eigen::Quaterniond q = scripted_turn(static_cast<double>(now_ns) * 1e-9);
  const Eigen::Vector3d p = centre_ - q * centre_;
  s.set_position(p);
  s.set_orientation(q);
  return s;
}

sim::BreathingSample ScriptedBreathing::at(std::int64_t now_ns) const {
  sim::BreathingSample b;
  b.t_s = static_cast<double>(now_ns) * 1e-9;
  b.dv_ml = scripted_volume_ml(b.t_s);
  b.v_ml = b.dv_ml;
  return b;
}

}  // namespace lungar::platform::bench
