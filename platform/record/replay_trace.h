/// @file replay_trace.h
/// @brief `lungar replay --trace-csv`: one row per replayed frame (session time, breathing time, dV, each lung's dV,
///        the pathologies drawn), so that a test or a plot compares the replay with its record.
/// @ingroup platform
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "platform/record/session_playback.h"
#include "platform/runtime/frame_listener.h"
#include "platform/runtime/lung_course.h"

namespace lungar::platform::record {

class ReplayTrace final : public FrameListener {
 public:
  /// `course`: whose pathologies each row says (null: none, the column empty); room for `rows` rows is made now, so
  /// that on_frame allocates nothing until they are used up.
  ReplayTrace(std::shared_ptr<const SessionPlayback> playback, std::shared_ptr<const LungCourse> course,
              std::size_t rows);
  void on_frame(const FrameState& state) override;
  /// The CSV: a header naming each lung (`lungs`, the record's), then a row per frame.
  std::string csv(const std::vector<std::string>& lungs) const;
  std::size_t rows() const { return rows_.size(); }

 private:
  struct Row {
    double s, t_s, dv_ml;
    std::array<double, 2> lung_dv_ml;
    const std::string* pathologies;  ///< the course's label, which lives as long as the course
  };
  std::shared_ptr<const SessionPlayback> playback_;
  std::shared_ptr<const LungCourse> course_;
  std::vector<Row> rows_;
};

}  // namespace lungar::platform::record
