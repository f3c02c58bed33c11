/// @file pathology_course.h
/// @brief A scenario's pathology events as the lungs' course through the run: a tension pneumothorax dropping
///        over 15 s, a needle decompression re-expanding the lung over 20 s. Each event's end state is the healthy
///        asset with the pathologies then present, mapped from the drawn one lung by lung (sim/pathology/
///        lung_shapes.h); between them the lungs blend, eased in and out.
/// @ingroup platform
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "config/base/result.h"
#include "config/scenario.h"
#include "platform/runtime/lung_course.h"
#include "sim/asset/baked_asset.h"
#include "sim/pathology/pathology_timeline.h"

namespace lungar::platform {

/// The pathologies from the start (`start`: the settings' and the scenario's own) and the scenario's pathology
/// events (none without a scenario).
sim::PathologyTimeline timeline_of(const std::vector<std::string>& start, const config::Scenario* scenario);

class PathologyCourse : public LungCourse {
 public:
  /// `healthy`: the asset before any pathology; `drawn`: some state of it, as on the GPU. The course starts with
  /// the timeline's start (mapped from `drawn`, which is the identity when `drawn` has those) and follows its
  /// events. An error names the event and what is wrong: a spec that does not parse, a removal of what is not
  /// there, a change that is not one of shape (a consolidation, or an ARDS coming or going: given for the whole
  /// scenario instead; a consolidation the drawn lungs do not have).
  static Result<std::shared_ptr<PathologyCourse>> create(const sim::BakedAsset& healthy, const sim::BakedAsset& drawn,
                                                         const sim::PathologyTimeline& timeline);
  /// The scenario's time zero (monotonic ns), when the breathing starts.
  void start_at(std::int64_t t0_ns) { t0_ns_ = t0_ns; }
  const std::vector<sim::LungShape>& at(std::int64_t now_ns) override;
  /// `pathologies`: those in force at the last at(), one coming or going counted as present while it changes (a
  /// tension pneumothorax shows from its onset); `pathologies_changing`: the one under way (empty: none).
  void add_stats(nlohmann::json& stats) const override;
  /// "pneumothorax:right:30:tension (coming)", "none"...: the pathologies in force at the last at().
  const std::string* pathologies_now() const override { return &label_now(); }
  /// The same at scenario time t_s (for tests, plots and a classroom's shared time).
  const std::vector<sim::LungShape>& at_seconds(double t_s);
  const sim::PathologyTimeline& timeline() const { return timeline_; }

 private:
  struct Step {
    double at_s = 0, over_s = 0;
    std::vector<sim::LungShape> to;
    std::string changing;                     ///< the spec that comes or goes
    std::string label_under_way, label_done;  ///< pathologies_now() while it changes, and after
  };
  const std::string& label_now() const;
  /// The lungs at t_s when the first `begun` steps have begun.
  std::vector<sim::LungShape> state_at(double t_s, std::size_t begun) const;
  sim::PathologyTimeline timeline_;
  std::size_t done_ = 0;    ///< events done at the last at(): what the stats JSON's `pathologies` lists
  bool under_way_ = false;  ///< the event after those done was changing the lungs at the last at()
  std::string start_label_;
  std::vector<sim::LungShape> start_;
  std::vector<Step> steps_;
  std::vector<sim::LungShape> now_;
  std::int64_t t0_ns_ = 0;
};

}  // namespace lungar::platform
