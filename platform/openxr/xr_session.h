/// @file xr_session.h
/// @brief An OpenXR session (bound to lungar's EGL context, or headless), its reference spaces, and its event
/// pump: state changes go through the Lifecycle, which begins and ends the session as the runtime asks.
#pragma once

#include <functional>
#include <string>

#include "config/base/result.h"
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
  Session(Session&& other) noexcept;
  Session& operator=(Session&& other) noexcept;
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  ~Session();

  /// Handles every pending event: begins the session on READY, ends it on STOPPING, logs one line per change.
  /// Returns what the owner must still do: DestroySession (EXITING), ReconnectSession (LOSS_PENDING),
  /// ReconnectInstance (instance loss pending), else None.
  Result<LifecycleAction> poll_events();
  /// xrRequestExitSession once the session runs (else the session is simply over): STOPPING and EXITING follow.
  Status request_exit();

  XrSession handle() const { return session_; }
  XrSpace app_space() const { return app_space_; }    ///< LOCAL or STAGE
  XrSpace view_space() const { return view_space_; }  ///< the head (VIEW)
  XrReferenceSpaceType space_type() const { return space_type_; }
  const Lifecycle& lifecycle() const { return lifecycle_; }

 private:
  Session() = default;
  Status create_spaces(XrReferenceSpaceType wanted);
  void destroy();
  LifecycleAction apply(LifecycleAction action);
  XrInstance instance_ = XR_NULL_HANDLE;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace app_space_ = XR_NULL_HANDLE;
  XrSpace view_space_ = XR_NULL_HANDLE;
  XrReferenceSpaceType space_type_ = XR_REFERENCE_SPACE_TYPE_LOCAL;
  Lifecycle lifecycle_;
  LogFn log_;
  std::string error_;  ///< a failed xrBeginSession/xrEndSession inside poll_events()
};

}  // namespace lungar::platform::openxr
