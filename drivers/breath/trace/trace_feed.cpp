/// @file trace_feed.cpp
/// @brief A recorded trace's samples to the follower (trace_feed.h).
#include "drivers/breath/trace/trace_feed.h"

#include <nlohmann/json.hpp>

#include "config/base/breath_source_names.h"

namespace lungar::breath {

void TraceFeed::feed(double t_s, Followers& followers) {
  for (; next_ < trace_.samples.size() && trace_.samples[next_].t_s <= t_s; ++next_)
    followers.breath.add(trace_.samples[next_].t_s, trace_.samples[next_].value);
}

void TraceFeed::add_stats(nlohmann::json& stats) const {
  stats["breath_source"] = kBreathSourceNames.name(BreathSource::Trace);
  stats["breath_file"] = path_;
  stats["breath_format"] = trace_.format;
  // Samples the recorder flagged (RPM's validflag) that this trace still holds: followed.
  long flagged = 0;
  for (const sim::TraceSample& s : trace_.samples) flagged += s.flagged ? 1 : 0;
  stats["breath_flagged_samples"] = flagged;
  stats["breath_invalid_samples"] = 0;
}

Result<std::shared_ptr<TraceFeed>> open_trace_feed(const std::string& path, const TraceSettings& settings,
                                                   const std::function<void(const std::string&)>& log) {
  auto trace = sim::read_breath_trace(path);
  if (!trace) return Error{trace.error()};
  const bool skip = settings.skip_flagged && trace->flagged > 0;
  log("breathing: following " + path + " (" + std::to_string(trace->samples.size()) + " samples" +
      (trace->marker ? ", a marker read along its breathing axis" : "") +
      (trace->flagged > 0 ? ", " + std::to_string(trace->flagged) + " flagged by the recorder, " +
                                (skip ? "skipped" : "followed")
                          : std::string()) +
      "), the model before and after");
  if (skip) trace = sim::without_flagged(trace.take());
  return std::make_shared<TraceFeed>(trace.take(), path);
}

}  // namespace lungar::breath
