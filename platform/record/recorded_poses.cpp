/// @file recorded_poses.cpp
/// @brief The recorded patient between two frames.
#include "platform/record/recorded_poses.h"

#include <algorithm>
#include <cstdio>

namespace lungar::platform::record {

std::string RecordedPoses::describe() const {
  const SessionRecord& r = playback_->record();
  char span[96];
  std::snprintf(span, sizeof span, " (%zu frames, %.1f s)", r.frames.size(),
                playback_->last_s() - playback_->first_s());
  return "session record " + r.path + span;
}

drivers::PoseSample RecordedPoses::latest(drivers::Role role, std::int64_t now_ns) const {
  if (role != drivers::Role::Patient) return {};
  const double s = playback_->session_s(now_ns);
  last_asked_s_ = std::max(last_asked_s_, s);
  ++given_;
  const SessionPlayback::Between b = playback_->around(s);
  drivers::PoseSample p = b.before->patient;
  p.flags |= drivers::kPoseValid;  // what the frame used: a stale pose was drawn all the same
  p.t_device_ns = p.t_arrival_ns = now_ns;
  if (b.u == 0) return p;
  p.set_position((1.0 - b.u) * b.before->patient.position() + b.u * b.after->patient.position());
  p.set_orientation(b.before->patient.orientation().slerp(b.u, b.after->patient.orientation()));
  return p;
}

drivers::PoseSample RecordedPoses::predicted(drivers::Role role, std::int64_t t_ns, std::int64_t) const {
  return latest(role, t_ns);
}

bool RecordedPoses::finished() const { return last_asked_s_ >= playback_->last_s(); }

SourceCounters RecordedPoses::counters(double wall_s) const {
  SourceCounters c;
  c.reports = given_;
  c.rate_hz = wall_s > 0 ? static_cast<double>(given_) / wall_s : 0.0;
  c.state = state();
  return c;
}

}  // namespace lungar::platform::record
