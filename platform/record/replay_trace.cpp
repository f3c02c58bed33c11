/// @file replay_trace.cpp
/// @brief The replayed frames' rows, and their CSV.
#include "platform/record/replay_trace.h"

#include <cmath>
#include <cstdio>

namespace lungar::platform::record {

ReplayTrace::ReplayTrace(std::shared_ptr<const SessionPlayback> playback, std::shared_ptr<const LungCourse> course,
                         std::size_t rows)
    : playback_(std::move(playback)), course_(std::move(course)) {
  rows_.reserve(rows);
}

void ReplayTrace::on_frame(const FrameState& state) {
  rows_.push_back({playback_->session_s(state.now_ns), state.breath.t_s, state.breath.dv_ml, state.lung_dv_ml,
                   course_ ? course_->pathologies_now() : nullptr});
}

std::string ReplayTrace::csv(const std::vector<std::string>& lungs) const {
  std::string out = "session_s,breath_s,dv_ml";
  for (std::size_t l = 0; l < 2; ++l) out += ",dv_ml_" + (l < lungs.size() ? lungs[l] : "lung" + std::to_string(l));
  out += ",pathologies\n";
  for (const Row& r : rows_) {
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "%.6f,%.6f,%.6f,%.6f,%.6f,", r.s, r.t_s, r.dv_ml,
                  std::isfinite(r.lung_dv_ml[0]) ? r.lung_dv_ml[0] : 0.0,
                  std::isfinite(r.lung_dv_ml[1]) ? r.lung_dv_ml[1] : 0.0);
    out += numbers;
    const std::string label = r.pathologies ? *r.pathologies : "";
    out += label.find(',') == std::string::npos ? label : "\"" + label + "\"";  // labels hold no quote
    out += '\n';
  }
  return out;
}

}  // namespace lungar::platform::record
