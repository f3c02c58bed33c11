/// @file session_playback.cpp
/// @brief Finding the recorded frames around a session time.
#include "platform/record/session_playback.h"

#include <algorithm>
#include <cassert>

namespace lungar::platform::record {

SessionPlayback::SessionPlayback(std::shared_ptr<const SessionRecord> record, std::int64_t start_ns)
    : record_(std::move(record)), start_ns_(start_ns) {
  assert(!record_->frames.empty() && "a playback needs a frame");
  first_s_ = record_->frames.front().s;
  last_s_ = record_->frames.back().s;
}

SessionPlayback::Between SessionPlayback::around(double s) const {
  const std::vector<RecordedFrame>& f = record_->frames;
  const auto after = std::upper_bound(f.begin(), f.end(), s, [](double t, const RecordedFrame& x) { return t < x.s; });
  if (after == f.begin()) return {&f.front(), &f.front(), 0.0};
  if (after == f.end()) return {&f.back(), &f.back(), 0.0};
  const RecordedFrame& before = *(after - 1);
  if (s - before.s <= kSnapS) return {&before, &before, 0.0};
  if (after->s - s <= kSnapS) return {&*after, &*after, 0.0};
  return {&before, &*after, (s - before.s) / (after->s - before.s)};
}

}  // namespace lungar::platform::record
