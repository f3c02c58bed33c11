/// @file recorded_poses.h
/// @brief A replay's poses: the patient as the recorded frames had it, linear in position and spherical in
///        orientation between them; no head pose (the runtime draws from its default viewpoint, or the HMD's own).
/// @ingroup platform
#pragma once

#include <memory>

#include "platform/record/session_playback.h"
#include "platform/runtime/pose_source.h"

namespace lungar::platform::record {

class RecordedPoses final : public PoseSource {
 public:
  explicit RecordedPoses(std::shared_ptr<const SessionPlayback> playback) : playback_(std::move(playback)) {}

  std::string describe() const override;
  /// The patient's recorded pose at `now_ns`; an invalid sample for every other role.
  drivers::PoseSample latest(drivers::Role role, std::int64_t now_ns) const override;
  /// The same (the record has every time it asks for).
  drivers::PoseSample predicted(drivers::Role role, std::int64_t t_ns, std::int64_t max_ahead_ns) const override;
  const char* state() const override { return finished() ? "finished" : "replaying"; }
  /// Once a time at or past the last frame was asked for.
  bool finished() const override;
  /// reports: the patient poses given.
  SourceCounters counters(double wall_s) const override;
  void stop() override {}

 private:
  std::shared_ptr<const SessionPlayback> playback_;
  mutable double last_asked_s_ = -1e300;  ///< the frame loop's alone
  mutable std::uint64_t given_ = 0;
};

}  // namespace lungar::platform::record
