/// @file xr_lifecycle.cpp
/// @brief The session state machine's decisions and lines.
#include "platform/openxr/xr_lifecycle.h"

namespace lungar::platform::openxr {

const char* to_string(XrSessionState state) {
  switch (state) {
    case XR_SESSION_STATE_IDLE: return "IDLE";
    case XR_SESSION_STATE_READY: return "READY";
    case XR_SESSION_STATE_SYNCHRONIZED: return "SYNCHRONIZED";
    case XR_SESSION_STATE_VISIBLE: return "VISIBLE";
    case XR_SESSION_STATE_FOCUSED: return "FOCUSED";
    case XR_SESSION_STATE_STOPPING: return "STOPPING";
    case XR_SESSION_STATE_LOSS_PENDING: return "LOSS_PENDING";
    case XR_SESSION_STATE_EXITING: return "EXITING";
    default: return "UNKNOWN";
  }
}

bool Lifecycle::reached(XrSessionState state) const {
  const auto bit = static_cast<unsigned>(state);
  return bit < 32 && (reached_ & (1u << bit)) != 0;
}

LifecycleAction Lifecycle::on_session_state(XrSessionState state) {
  state_ = state;
  if (static_cast<unsigned>(state) < 32) reached_ |= 1u << static_cast<unsigned>(state);
  const std::string name = std::string("OpenXR: session ") + to_string(state);
  switch (state) {
    case XR_SESSION_STATE_READY:
      line_ = name + ": beginning the session";
      return LifecycleAction::BeginSession;
    case XR_SESSION_STATE_STOPPING:
      line_ = name + ": ending the session" + (exit_requested_ ? " (lungar asked to exit)" : " (the runtime asked)");
      return LifecycleAction::EndSession;
    case XR_SESSION_STATE_EXITING:
      line_ = name + ": session over";
      return LifecycleAction::DestroySession;
    case XR_SESSION_STATE_LOSS_PENDING:
      line_ = name + ": the runtime is losing the headset; ending the session, reconnecting when it is back";
      return LifecycleAction::ReconnectSession;
    case XR_SESSION_STATE_SYNCHRONIZED: line_ = name + ": frames paced, not yet shown"; break;
    case XR_SESSION_STATE_VISIBLE: line_ = name + ": frames shown, no input focus"; break;
    case XR_SESSION_STATE_FOCUSED: line_ = name + ": frames shown, input focus"; break;
    case XR_SESSION_STATE_IDLE:
      line_ = name + (reached(XR_SESSION_STATE_READY) ? ": ended" : ": waiting for the runtime to be ready");
      break;
    default: line_ = name; break;
  }
  return LifecycleAction::None;
}

LifecycleAction Lifecycle::on_instance_loss_pending() {
  line_ = "OpenXR: instance loss pending (the runtime is restarting or going away); destroying the instance, "
          "reconnecting when the runtime is back";
  return LifecycleAction::ReconnectInstance;
}

}  // namespace lungar::platform::openxr
