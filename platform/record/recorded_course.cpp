/// @file recorded_course.cpp
/// @brief Each recorded timeline's course, and the one in force at a session time.
#include "platform/record/recorded_course.h"

#include <algorithm>

namespace lungar::platform::record {

Result<std::shared_ptr<RecordedCourse>> RecordedCourse::create(std::shared_ptr<const SessionPlayback> playback,
                                                               const sim::BakedAsset& healthy,
                                                               const sim::BakedAsset& drawn) {
  const SessionRecord& r = playback->record();
  const bool any_event = std::any_of(r.timelines.begin(), r.timelines.end(),
                                     [](const RecordedTimeline& t) { return !t.timeline.events.empty(); });
  if (!any_event) return std::shared_ptr<RecordedCourse>();
  auto course = std::shared_ptr<RecordedCourse>(new RecordedCourse());
  course->playback_ = std::move(playback);
  for (const RecordedTimeline& t : r.timelines) {
    auto made = PathologyCourse::create(healthy, drawn, t.timeline);
    if (!made) return made.with_context(r.path + ":" + std::to_string(t.line) + ": timeline: ");
    course->versions_.push_back({t.s, made.take()});
  }
  course->now_ = course->versions_.front().course.get();
  return course;
}

const std::vector<sim::LungShape>& RecordedCourse::at(std::int64_t now_ns) {
  const double s = playback_->session_s(now_ns);
  // The last version noted at or before s (the first before any): what the live course followed then.
  const auto after =
      std::upper_bound(versions_.begin(), versions_.end(), s, [](double t, const Version& v) { return t < v.from_s; });
  now_ = (after == versions_.begin() ? versions_.front() : *(after - 1)).course.get();
  const SessionPlayback::Between b = playback_->around(s);
  return now_->at_seconds(b.lerp([](const RecordedFrame& f) { return f.breath.t_s; }));
}

}  // namespace lungar::platform::record
