/// @file openxr_output.h
/// @brief lungar's frames on an OpenXR headset: the instance, the session bound to lungar's EGL context, one colour
/// swapchain per view (sRGB preferred) with its depth swapchain (XR_KHR_composition_layer_depth), and the frame:
/// xrWaitFrame paces it, xrLocateViews at the predicted display time gives each eye, xrEndFrame submits the
/// projection layer. A lost headset or a restarting runtime is reconnected, with one line each.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "config/base/result.h"
#include "platform/egl/egl_context.h"
#include "platform/openxr/xr_instance.h"
#include "platform/openxr/xr_session.h"
#include "platform/openxr/xr_view_targets.h"
#include "render/stereo_view.h"

namespace lungar::platform::openxr {

struct OpenXrOptions {
  InstanceOptions instance;
  XrReferenceSpaceType space = XR_REFERENCE_SPACE_TYPE_LOCAL;  ///< or STAGE
  float near_mm = 50.f;
  float far_mm = 5000.f;
  /// The reference space's pose in lungar's world (mm): where the runtime's tracking sits relative to the
  /// trackers that place the patient. Part of the registration.
  glm::mat4 world_from_space{1.f};
  LogFn log;
};

/// One frame's timing, from xrWaitFrame.
struct XrFrameTiming {
  bool begun = false;          ///< xrBeginFrame was called: end_frame() must follow
  bool should_render = false;  ///< the runtime will show this frame: locate and draw the views
  std::int64_t display_ns = 0; ///< predicted display time, CLOCK_MONOTONIC nanoseconds
  std::int64_t period_ns = 0;  ///< predicted display period
};

class OpenXrOutput {
 public:
  /// Loads the runtime, binds the context (current on this thread) and makes the swapchains.
  static Result<std::unique_ptr<OpenXrOutput>> create(EglContext& context, const OpenXrOptions& options);
  ~OpenXrOutput();
  OpenXrOutput(const OpenXrOutput&) = delete;
  OpenXrOutput& operator=(const OpenXrOutput&) = delete;

  /// Handles the runtime's events, then xrWaitFrame + xrBeginFrame while the session runs: this paces the loop.
  /// While it does not (waiting for READY, reconnecting) it waits a little and returns begun = false.
  Result<XrFrameTiming> wait_frame();
  /// xrLocateViews at the predicted display time. `world_from_head` null: the runtime's head, placed in the world
  /// by OpenXrOptions::world_from_space; else lungar's head (head frame: +x right, +y up, -z ahead, mm), with
  /// each view's pose relative to the runtime's head (its IPD and eye offsets) and its field of view.
  /// Empty when the runtime cannot locate the views now (then nothing is submitted).
  Result<std::span<const render::EyeView>> locate_views(const glm::mat4* world_from_head = nullptr);
  /// Acquires view i's images (once a frame), binds its framebuffer and sets the viewport to the whole image.
  Status bind_view(std::size_t view);
  /// Reads view i's colour image, top row first (after drawing, before end_frame()).
  Status read_view(std::size_t view, std::vector<std::uint8_t>& rgba);
  /// Releases the images and calls xrEndFrame: the projection layer (with depth) when views were drawn.
  Status end_frame();
  /// Asks the runtime to end the session (STOPPING, then EXITING follow through wait_frame()).
  Status request_exit();
  /// The session is over (EXITING handled): the loop stops.
  bool exited() const { return exited_; }

  const RuntimeInfo& runtime() const { return runtime_; }
  const Lifecycle& lifecycle() const;
  std::uint64_t frames_submitted() const { return frames_submitted_; }
  double predicted_display_period_ms() const { return static_cast<double>(period_ns_) * 1e-6; }
  std::size_t view_count() const { return targets_.count(); }
  int view_width() const { return targets_.width(); }
  int view_height() const { return targets_.height(); }
  /// "GL_SRGB8_ALPHA8, depth GL_DEPTH_COMPONENT32F", as logged at start.
  const std::string& formats() const { return targets_.formats(); }
  /// The located views (in the reference space) of the last locate_views(), for tests.
  std::span<const XrView> located() const { return {views_.data(), views_.size()}; }

 private:
  OpenXrOutput(EglContext& context, const OpenXrOptions& options);
  Status connect();
  void disconnect(bool instance_too);
  Status handle(LifecycleAction action);
  void log(const std::string& line) const;

  EglContext& context_;
  OpenXrOptions options_;
  std::optional<Instance> instance_;
  std::optional<Session> session_;
  ViewTargets targets_;
  RuntimeInfo runtime_;
  XrEnvironmentBlendMode blend_ = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  std::array<XrView, 2> views_{};
  std::array<XrView, 2> views_in_head_{};
  std::array<render::EyeView, 2> eyes_{};
  XrFrameState frame_ = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
  bool begun_ = false;
  bool located_ = false;
  bool exited_ = false;
  std::int64_t reconnect_at_ns_ = -1;  ///< >= 0 while disconnected: when to try again
  bool reconnect_failed_logged_ = false;
  std::uint64_t frames_submitted_ = 0;
  std::int64_t period_ns_ = 0;
};

}  // namespace lungar::platform::openxr
