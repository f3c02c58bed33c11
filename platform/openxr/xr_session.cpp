/// @file xr_session.cpp
/// @brief Session creation, reference spaces and the event pump.
#include "platform/openxr/xr_session.h"

#include <utility>
#include <vector>

#include "platform/openxr/xr_error.h"

namespace lungar::platform::openxr {

Result<Session> Session::create(const Instance& instance, const XrGraphicsBindingEGLMNDX* binding,
                                XrReferenceSpaceType space, LogFn log) {
  Session s;
  s.instance_ = instance.handle();
  s.log_ = std::move(log);
  auto info = xr_struct<XrSessionCreateInfo>(XR_TYPE_SESSION_CREATE_INFO);
  info.next = binding;
  info.systemId = instance.system();
  if (XrResult r = xrCreateSession(instance.handle(), &info, s.session_.out()); XR_FAILED(r)) {
    return fail(xr_error(instance.handle(), binding ? "xrCreateSession(XR_MNDX_egl_enable)" : "xrCreateSession", r));
  }
  if (auto spaces = s.create_spaces(space); !spaces) return fail(spaces.error());
  return s;
}

Status Session::create_spaces(XrReferenceSpaceType wanted) {
  std::uint32_t count = 0;
  XrResult r = xrEnumerateReferenceSpaces(session_.get(), 0, &count, nullptr);
  if (XR_FAILED(r)) return fail(xr_error(instance_, "xrEnumerateReferenceSpaces", r));
  std::vector<XrReferenceSpaceType> offered(count);
  r = xrEnumerateReferenceSpaces(session_.get(), count, &count, offered.data());
  if (XR_FAILED(r)) return fail(xr_error(instance_, "xrEnumerateReferenceSpaces", r));
  space_type_ = XR_REFERENCE_SPACE_TYPE_LOCAL;  // every runtime has LOCAL
  for (auto t : offered) {
    if (t == wanted) space_type_ = wanted;
  }
  if (space_type_ != wanted && log_) log_("OpenXR: the runtime has no STAGE space; poses are in LOCAL");
  auto info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
  info.poseInReferenceSpace.orientation.w = 1.f;
  info.referenceSpaceType = space_type_;
  if (r = xrCreateReferenceSpace(session_.get(), &info, app_space_.out()); XR_FAILED(r)) {
    return fail(xr_error(instance_, "xrCreateReferenceSpace", r));
  }
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  if (r = xrCreateReferenceSpace(session_.get(), &info, view_space_.out()); XR_FAILED(r)) {
    return fail(xr_error(instance_, "xrCreateReferenceSpace(VIEW)", r));
  }
  return ok();
}

// Begins or ends the session where the lifecycle says so; passes the rest to the owner.
LifecycleAction Session::apply(LifecycleAction action) {
  if (action == LifecycleAction::BeginSession) {
    auto begin = xr_struct<XrSessionBeginInfo>(XR_TYPE_SESSION_BEGIN_INFO);
    begin.primaryViewConfigurationType = Instance::kViewConfiguration;
    if (XrResult r = xrBeginSession(session_.get(), &begin); XR_FAILED(r)) {
      error_ = xr_error(instance_, "xrBeginSession", r);
    } else {
      lifecycle_.on_begun();
    }
    return LifecycleAction::None;
  }
  if (action == LifecycleAction::EndSession || (action == LifecycleAction::ReconnectSession && lifecycle_.running())) {
    lifecycle_.on_ended();
    if (XrResult r = xrEndSession(session_.get()); XR_FAILED(r)) error_ = xr_error(instance_, "xrEndSession", r);
    return action == LifecycleAction::EndSession ? LifecycleAction::None : action;
  }
  return action;
}

Result<LifecycleAction> Session::poll_events() {
  LifecycleAction pending = LifecycleAction::None;
  auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
  XrResult r;
  while ((r = xrPollEvent(instance_, &event)) == XR_SUCCESS) {
    LifecycleAction action = LifecycleAction::None;
    bool lifecycle_event = false;
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
      lifecycle_event = changed.session == session_.get();
      if (lifecycle_event) action = lifecycle_.on_session_state(changed.state);
    } else if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
      lifecycle_event = true;
      action = lifecycle_.on_instance_loss_pending();
    } else if (event.type == XR_TYPE_EVENT_DATA_EVENTS_LOST && log_) {
      const auto& lost = reinterpret_cast<const XrEventDataEventsLost&>(event);
      log_("OpenXR: the runtime dropped " + std::to_string(lost.lostEventCount) + " events (queue full)");
    }
    if (lifecycle_event && log_) log_(lifecycle_.last_line());
    action = apply(action);
    if (!error_.empty()) return fail(std::exchange(error_, {}));
    if (action != LifecycleAction::None) pending = action;
    event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
  }
  if (XR_FAILED(r)) return fail(xr_error(instance_, "xrPollEvent", r));
  return pending;
}

Status Session::request_exit() {
  lifecycle_.on_exit_requested();
  if (!lifecycle_.running()) return ok();
  if (XrResult r = xrRequestExitSession(session_.get()); XR_FAILED(r)) {
    return fail(xr_error(instance_, "xrRequestExitSession", r));
  }
  return ok();
}

}  // namespace lungar::platform::openxr
