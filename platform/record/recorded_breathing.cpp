/// @file recorded_breathing.cpp
/// @brief The recorded breath between two frames.
#include "platform/record/recorded_breathing.h"

#include <nlohmann/json.hpp>

namespace lungar::platform::record {

sim::BreathingSample RecordedBreathing::at(std::int64_t now_ns) const {
  const SessionPlayback::Between b = playback_->around(playback_->session_s(now_ns));
  sim::BreathingSample out = b.before->breath;  // phase and breath index: the frame's before
  out.t_s = b.lerp([](const RecordedFrame& f) { return f.breath.t_s; });
  out.p_cmh2o = b.lerp([](const RecordedFrame& f) { return f.breath.p_cmh2o; });
  out.p_applied_cmh2o = b.lerp([](const RecordedFrame& f) { return f.breath.p_applied_cmh2o; });
  out.v_ml = b.lerp([](const RecordedFrame& f) { return f.breath.v_ml; });
  out.v_frc_ml = b.lerp([](const RecordedFrame& f) { return f.breath.v_frc_ml; });
  out.dv_ml = b.lerp([](const RecordedFrame& f) { return f.breath.dv_ml; });
  for (std::size_t l = 0; l < out.lung_dv_ml.size(); ++l)  // NaN (the source measured no lung) stays NaN
    out.lung_dv_ml[l] = b.lerp([l](const RecordedFrame& f) { return f.breath.lung_dv_ml[l]; });
  return out;
}

void RecordedBreathing::add_stats(nlohmann::json& stats) const { stats["breath_source"] = "replay"; }

}  // namespace lungar::platform::record
