/// @file xr_lifecycle.h
/// @brief The session's life as OpenXR states it (IDLE -> READY -> SYNCHRONIZED -> VISIBLE -> FOCUSED -> STOPPING
/// -> IDLE -> EXITING, or LOSS_PENDING; instance loss when the runtime restarts): what lungar does on each event,
/// and the one line it logs. Pure: no OpenXR calls, so every branch is tested without a runtime that takes it.
#pragma once

#include <cstdint>
#include <string>

#include "platform/openxr/xr_headers.h"

namespace lungar::platform::openxr {

/// What the caller does after an event.
enum class LifecycleAction {
  None,
  BeginSession,     ///< READY: xrBeginSession, then frames
  EndSession,       ///< STOPPING: xrEndSession
  DestroySession,   ///< EXITING: the session is over (asked for, or the runtime ended it)
  ReconnectSession, ///< LOSS_PENDING: end and destroy the session, then create one again when the headset is back
  ReconnectInstance ///< instance loss pending (runtime restart): destroy everything, create the instance again
};

const char* to_string(XrSessionState state);

class Lifecycle {
 public:
  /// XrEventDataSessionStateChanged.
  LifecycleAction on_session_state(XrSessionState state);
  /// XrEventDataInstanceLossPending.
  LifecycleAction on_instance_loss_pending();
  /// lungar wants to stop (frames done, Ctrl-C): after xrRequestExitSession, STOPPING and EXITING follow.
  void on_exit_requested() { exit_requested_ = true; }
  /// xrBeginSession succeeded / xrEndSession was called.
  void on_begun() { running_ = true; }
  void on_ended() { running_ = false; }

  XrSessionState state() const { return state_; }
  /// Between xrBeginSession and xrEndSession: the frame loop calls xrWaitFrame/xrBeginFrame/xrEndFrame.
  bool running() const { return running_; }
  /// VISIBLE or FOCUSED: what is submitted is seen (SYNCHRONIZED: frames are paced, not shown).
  bool visible() const { return state_ == XR_SESSION_STATE_VISIBLE || state_ == XR_SESSION_STATE_FOCUSED; }
  bool exit_requested() const { return exit_requested_; }
  /// Whether `state` was entered at least once.
  bool reached(XrSessionState state) const;
  /// The line that tells what the last event did, e.g. "OpenXR: session READY: beginning the session".
  const std::string& last_line() const { return line_; }

 private:
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  bool running_ = false;
  bool exit_requested_ = false;
  std::uint32_t reached_ = 0;  ///< bit per XrSessionState
  std::string line_;
};

}  // namespace lungar::platform::openxr
