/// @file recorded_course.h
/// @brief A replay's lungs: the recorded pathology timeline as it stood at each session time (the instructor may
///        have changed it during the class), each version a PathologyCourse evaluated at the recorded breathing time.
/// @ingroup platform
#pragma once

#include <memory>
#include <vector>

#include "config/base/result.h"
#include "platform/record/session_playback.h"
#include "platform/runtime/pathology_course.h"
#include "sim/asset/baked_asset.h"

namespace lungar::platform::record {

class RecordedCourse final : public LungCourse {
 public:
  /// A course for every timeline the record noted (`healthy`: the asset before any pathology, `drawn`: as on the
  /// GPU); none when no timeline has an event (the lungs stay as loaded). An error names the record's line.
  static Result<std::shared_ptr<RecordedCourse>> create(std::shared_ptr<const SessionPlayback> playback,
                                                        const sim::BakedAsset& healthy, const sim::BakedAsset& drawn);
  const std::vector<sim::LungShape>& at(std::int64_t now_ns) override;
  const std::string* pathologies_now() const override { return now_->pathologies_now(); }
  void add_stats(nlohmann::json& stats) const override { now_->add_stats(stats); }

 private:
  struct Version {
    double from_s;
    std::shared_ptr<PathologyCourse> course;
  };
  std::shared_ptr<const SessionPlayback> playback_;
  std::vector<Version> versions_;   ///< in the order noted
  PathologyCourse* now_ = nullptr;  ///< the version of the last at()
};

}  // namespace lungar::platform::record
