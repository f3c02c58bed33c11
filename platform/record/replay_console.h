/// @file replay_console.h
/// @brief `lungar replay SESSION --console [ADDR:]PORT`: the instructor's console page served read-only over a
///        replay. Its live view is the record's state at the replay's session time (the cursor): the breath and the
///        last half second of recorded frames, the lungs' orientation, the pathologies drawn, the stations as last
///        recorded, and every event of the record on the cursor's time axis, with `replay` {session_s, duration_s,
///        file} so that the page says "Replay" and disables its controls. Every control request is refused (409):
///        a replay changes nothing. The timeline CSV is the record's debrief sheet (timeline_csv.h).
/// @ingroup platform
///
/// Threads. on_frame() runs on the frame loop and only stores the frame's session time (an atomic, no allocation);
/// the rest comes on the console server's thread and reads the record, which no one changes.
///
/// Time axis: session time, seconds since the recording station's session started (the record's `s`), for the
/// cursor (`t_s`, replay.session_s), each event's `t_s` (when it was noted) and the samples: the axis of the
/// timeline CSV's session_s column. Each event's breathing time is kept as `breath_s`.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "platform/console/console_handler.h"
#include "platform/record/session_playback.h"
#include "platform/runtime/frame_listener.h"

namespace lungar::platform::record {

class ReplayConsole final : public console::ConsoleHandler, public FrameListener {
 public:
  /// The plot's samples: the recorded frames of the last this many seconds before the cursor.
  static constexpr double kSamplesS = 0.5;

  /// `playback`: the replay's (its clock turns a frame's time into session time; it has at least one frame).
  explicit ReplayConsole(std::shared_ptr<const SessionPlayback> playback);

  /// The frame loop: the cursor moves to the frame's session time. Allocates nothing.
  void on_frame(const FrameState& state) override;

  // ConsoleHandler.
  /// The record at the cursor (see the file's comment).
  std::string snapshot_json() override;
  /// 409 {"error": "a replay is read-only: ..."}: nothing changes.
  console::ControlReply control(const console::ConsoleUser& user, const nlohmann::json& request) override;
  /// record::timeline_csv of the record.
  std::string timeline_csv() override;
  /// Counted (the view's `refused`); the server logs the line.
  void refused(int status, const std::string& line) override;

  /// The view at session time `s` (snapshot_json() is this at the cursor).
  nlohmann::json view_at(double s) const;
  /// Session time of the frame drawn last; the record's first frame's before any.
  double cursor_s() const { return cursor_s_.load(std::memory_order_relaxed); }
  std::uint64_t refused_count() const { return refused_.load(std::memory_order_relaxed); }

 private:
  std::shared_ptr<const SessionPlayback> playback_;
  std::string file_;          ///< the record's file name (no folder: observers see it)
  nlohmann::json events_;     ///< every event of the record, made once
  std::string timeline_csv_;  ///< made once
  std::atomic<double> cursor_s_;
  std::atomic<std::uint64_t> refused_{0};
};

}  // namespace lungar::platform::record
