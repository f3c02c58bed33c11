/// @file xr_session.h
/// @brief An OpenXR session (bound to lungar's EGL context, or headless), its reference spaces, and its event
/// pump: state changes go through the Lifecycle, which begins and ends the session as the runtime asks.
#pragma once

#include <functional>
#include <string>

#include "config/base/result.h"
#include "config/base/unique_handle.h"
#include "platform/openxr/xr_headers.h"
#include "platform/openxr/xr_instance.h"
#include "platform/openxr/xr_lifecycle.h"

namespace lungar::platform::openxr {

using LogFn = std::function<void(const std::string&)>;

class Session {
 public:
  /// `binding` null: a headless session (the instance must have been made with InstanceOptions::headless).
  /// `space`: LOCAL or STAGE, the space poses are located in (STAGE falls back to LOCAL where the runtime has none).
  static Result<Session> create(const Instance& instance, const XrGraphicsBindingEGLMNDX* binding,
                                XrReferenceSpaceType space, LogFn log);
  Session(Session&&) noexcept = default;
  /// Not assignable: assigning over a live session would destroy it before its spaces.
  Session& operator=(Session&&) = delete;
  /// Handles every pending event: begins the session on READY, ends it on STOPPING, logs one line per change.
  /// Returns what the owner must still do: DestroySession (EXITING), ReconnectSession (LOSS_PENDING),
  /// ReconnectInstance (instance loss pending), else None.
  Result<LifecycleAction> poll_events();
  /// xrRequestExitSession once the session runs (else the session is simply over): STOPPING and EXITING follow.
  Status request_exit();

  XrSession handle() const { return session_.get(); }
  XrSpace app_space() const { return app_space_.get(); }    ///< LOCAL or STAGE
  XrSpace view_space() const { return view_space_.get(); }  ///< the head (VIEW)
  XrReferenceSpaceType space_type() const { return space_type_; }
  const Lifecycle& lifecycle() const { return lifecycle_; }

 private:
  Session() = default;
  Status create_spaces(XrReferenceSpaceType wanted);
  LifecycleAction apply(LifecycleAction action);
  XrInstance instance_ = XR_NULL_HANDLE;
  // Declared before its spaces, so that they are destroyed first.
  UniqueHandle<XrSession, xrDestroySession> session_;
  UniqueHandle<XrSpace, xrDestroySpace> app_space_;
  UniqueHandle<XrSpace, xrDestroySpace> view_space_;
  XrReferenceSpaceType space_type_ = XR_REFERENCE_SPACE_TYPE_LOCAL;
  Lifecycle lifecycle_;
  LogFn log_;
  std::string error_;  ///< a failed xrBeginSession/xrEndSession inside poll_events()
};

}  // namespace lungar::platform::openxr
