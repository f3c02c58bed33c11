/// @file trace_feed.h
/// @brief `--breath FILE`: a recorded respiratory surrogate (CSV t_s,value or a marker's t_s,x,y,z, a Varian RPM
///        .vxp, a NDI ExtMarker export; sim/breathing/breath_trace.h reads them), its samples given to the follower
///        at their own times from the run's start. Its settings sit beside it.
/// @ingroup breath
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "config/base/result.h"
#include "drivers/breath/source/surrogate_feed.h"
#include "sim/breathing/breath_trace.h"

namespace lungar::breath {

/// What a trace's reading takes from `[breathing]`.
struct TraceSettings {
  /// A Varian RPM trace's flagged samples (its validflag): followed, or skipped ([breathing] rpm_flagged = "skip").
  bool skip_flagged = false;
};

class TraceFeed final : public SurrogateFeed {
 public:
  TraceFeed(sim::BreathTrace trace, std::string path) : trace_(std::move(trace)), path_(std::move(path)) {}
  void feed(double t_s, Followers& followers) override;
  /// breath_source "trace", breath_file, breath_format, breath_flagged_samples, breath_invalid_samples.
  void add_stats(nlohmann::json& stats) const override;

 private:
  sim::BreathTrace trace_;
  std::string path_;
  std::size_t next_ = 0;
};

/// Reads the trace at `path` and says in `log` what it follows (its samples, a marker's axis, what the recorder
/// flagged); or the reader's one-line error.
Result<std::shared_ptr<TraceFeed>> open_trace_feed(const std::string& path, const TraceSettings& settings,
                                                   const std::function<void(const std::string&)>& log);

}  // namespace lungar::breath
