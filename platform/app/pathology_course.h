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

#include "config/base/result.h"
#include "config/scenario.h"
#include "platform/runtime/lung_course.h"
#include "sim/asset/baked_asset.h"

namespace lungar::platform {

class PathologyCourse : public LungCourse {
 public:
  /// `healthy`: the asset before any pathology; `drawn`: it with `start` (the pathologies at t = 0) applied, as on
  /// the GPU. None when the scenario has no pathology event. An error names the event and what is wrong: a spec
  /// that does not parse, a removal of what is not there, a change that is not one of shape (a consolidation or
  /// ARDS: given for the whole scenario instead).
  static Result<std::shared_ptr<PathologyCourse>> create(const sim::BakedAsset& healthy, const sim::BakedAsset& drawn,
                                                         const std::vector<std::string>& start,
                                                         const config::Scenario& scenario,
                                                         const std::function<void(const std::string&)>& log);
  /// The scenario's time zero (monotonic ns), when the breathing starts.
  void start_at(std::int64_t t0_ns) { t0_ns_ = t0_ns; }
  const std::vector<sim::LungShape>& at(std::int64_t now_ns) override;
  /// The same at scenario time t_s (for tests and plots).
  const std::vector<sim::LungShape>& at_seconds(double t_s);

 private:
  struct Step {
    double at_s = 0, over_s = 0;
    std::vector<sim::LungShape> to;
  };
  std::vector<sim::LungShape> start_;
  std::vector<Step> steps_;
  std::vector<sim::LungShape> now_;
  std::int64_t t0_ns_ = 0;
};

}  // namespace lungar::platform
