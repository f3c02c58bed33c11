/// @file scenario_patient.cpp
/// @brief A simulated patient's orientation track replaces the patient's measured orientation.
#include "platform/runtime/scenario_patient.h"

#include "config/base/clock.h"

namespace lungar::platform {

drivers::PoseSample ScenarioPatient::turned(drivers::PoseSample s, std::int64_t t_ns) const {
  if (s.role != drivers::Role::Patient) return s;
  const Eigen::Quaterniond q = track_->orientation_at(seconds_between(t0_ns_, t_ns));
  s.set_orientation(q);
  return s;
}

drivers::PoseSample ScenarioPatient::latest(drivers::Role role, std::int64_t now_ns) const {
  drivers::PoseSample s = inner_->latest(role, now_ns);
  s.role = role;
  return role == drivers::Role::Patient ? turned(s, now_ns) : s;
}

drivers::PoseSample ScenarioPatient::predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const {
  drivers::PoseSample s = inner_->predicted(role, t_ns, max_ahead_ns);
  s.role = role;
  return role == drivers::Role::Patient ? turned(s, t_ns) : s;
}

}  // namespace lungar::platform
