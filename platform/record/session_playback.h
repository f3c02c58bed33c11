/// @file session_playback.h
/// @brief A session record on the replay's clock: which session time a monotonic time plays, and the recorded frames
///        around a session time, which the replay's breathing, poses and course interpolate between.
/// @ingroup platform
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>

#include "platform/record/session_record.h"

namespace lungar::platform::record {

class SessionPlayback {
 public:
  /// Within this of a recorded frame's time a time is that frame's (the record keeps times to the microsecond): a
  /// replay stepping frame by frame gives each frame's own values, not a blend with its neighbour.
  static constexpr double kSnapS = 1e-6;

  /// The frames around a session time: `before` and `after` (the same frame at or outside the ends, or on one),
  /// and how far between them it is, from 0 to 1.
  struct Between {
    const RecordedFrame* before = nullptr;
    const RecordedFrame* after = nullptr;
    double u = 0;
    /// before + u (after - before) of what `of` takes from a frame.
    template <class Of>
    double lerp(const Of& of) const {
      return u == 0 ? of(*before) : of(*before) + u * (of(*after) - of(*before));
    }
  };

  /// `record` has at least one frame; its first frame plays at monotonic `start_ns`.
  SessionPlayback(std::shared_ptr<const SessionRecord> record, std::int64_t start_ns);

  /// The session time that plays at `now_ns`.
  double session_s(std::int64_t now_ns) const { return first_s_ + static_cast<double>(now_ns - start_ns_) * 1e-9; }
  /// The monotonic time at which session time `s` plays.
  std::int64_t ns_at(double s) const { return start_ns_ + std::llround((s - first_s_) * 1e9); }
  Between around(double s) const;
  /// Plays the first frame at `start_ns` from now on (a replay starts its clock once the scene is loaded).
  void start_at(std::int64_t start_ns) { start_ns_ = start_ns; }

  const SessionRecord& record() const { return *record_; }
  double first_s() const { return first_s_; }
  double last_s() const { return last_s_; }

 private:
  std::shared_ptr<const SessionRecord> record_;
  std::int64_t start_ns_;
  double first_s_, last_s_;
};

}  // namespace lungar::platform::record
