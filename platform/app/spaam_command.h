/// @file spaam_command.h
/// @brief `lungar calibrate-display` without --alignments: each eye in turn shows a crosshair at the session's
///        positions on the HMD; the user lines it up with the tracked point and confirms (Space or Enter),
///        Backspace undoes, Esc aborts with nothing written. Then the gathered alignments are saved and fitted by
///        the same path as the offline way. The loop meets the world through SpaamIo, so that a test can give it
///        poses and keys without a window or a tracker.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "config/base/result.h"
#include "drivers/pose/pose_sample.h"
#include "platform/app/calibrate_display_command.h"
#include "platform/registration/spaam_session.h"

namespace lungar::platform {

struct SpaamIo {
  std::function<bool()> poll;         ///< false once the user closed the screen (Esc): abort
  std::function<std::string()> keys;  ///< pressed since the last call: ' ' or '\n' confirms, '\b' undoes
  /// The head's pose and the pose of the sensor that carries the point (SpaamPoint::role), both now.
  std::function<std::array<drivers::PoseSample, 2>()> poses;
  /// Shows one frame of `session`'s target with `note` (what the last key did) under the prompt.
  std::function<Status(const SpaamSession& session, const std::string& note)> draw;
  std::function<void(const std::string&)> say;  ///< a line for the terminal
};

/// Runs `session` to its end: true once every position is confirmed, false when the user aborted; an error
/// when a frame cannot be drawn.
Result<bool> run_spaam(SpaamSession& session, const SpaamIo& io);

/// run_spaam, then the alignments to saved_alignments_path(o) and fit_and_report(); nothing is written when the
/// user aborts (exit code 1). The exit code.
int gather_and_fit(const CalibrateDisplayOptions& o, SpaamSession& session, const SpaamIo& io);

/// The interactive command: the settings' tracker and output (a window: display.output window or fullscreen, or
/// auto with DISPLAY set), the SPAAM screen on it, then gather_and_fit(). The exit code.
int run_spaam_calibration(const CalibrateDisplayOptions& o);

}  // namespace lungar::platform
