/// @file openxr_output.cpp
/// @brief The OpenXR frame: events, pacing, views, submission; connecting and reconnecting to the runtime.
#include "platform/openxr/openxr_output.h"

#include <chrono>
#include <cstdlib>
#include <thread>

#include "config/base/clock.h"
#include "platform/openxr/xr_egl_binding.h"
#include "platform/openxr/xr_error.h"
#include "platform/openxr/xr_runtime_quirks.h"
#include "platform/openxr/xr_view_math.h"
#include "render/frame_target.h"

namespace lungar::platform::openxr {
namespace {

constexpr std::int64_t kReconnectEveryNs = 1'000'000'000;
constexpr auto kIdleWait = std::chrono::milliseconds(10);  // waiting for READY: no xrWaitFrame to pace the loop

// The runtime's preferred blend mode (the first it lists): ADDITIVE on optical see-through glasses, OPAQUE on a
// closed headset.
Result<XrEnvironmentBlendMode> preferred_blend_mode(const Instance& instance) {
  const auto enumerate = [&](std::uint32_t capacity, std::uint32_t* count, XrEnvironmentBlendMode* modes) {
    return xrEnumerateEnvironmentBlendModes(instance.handle(), instance.system(), Instance::kViewConfiguration,
                                            capacity, count, modes);
  };
  std::uint32_t count = 0;
  XrResult r = enumerate(0, &count, nullptr);
  std::vector<XrEnvironmentBlendMode> modes(count);
  if (XR_SUCCEEDED(r)) r = enumerate(count, &count, modes.data());
  if (XR_FAILED(r)) return fail(xr_error(instance.handle(), "xrEnumerateEnvironmentBlendModes", r));
  if (modes.empty()) return fail("OpenXR: " + instance.runtime().text() + ": expected an environment blend mode");
  return modes[0];
}

const char* blend_name(XrEnvironmentBlendMode mode) {
  switch (mode) {
    case XR_ENVIRONMENT_BLEND_MODE_OPAQUE: return "opaque";
    case XR_ENVIRONMENT_BLEND_MODE_ADDITIVE: return "additive (see-through)";
    case XR_ENVIRONMENT_BLEND_MODE_ALPHA_BLEND: return "alpha blend (passthrough)";
    default: return "unknown";
  }
}

}  // namespace

OpenXrOutput::OpenXrOutput(EglContext& context, const OpenXrOptions& options) : context_(context), options_(options) {}

OpenXrOutput::~OpenXrOutput() { disconnect(true); }

Result<std::unique_ptr<OpenXrOutput>> OpenXrOutput::create(EglContext& context, const OpenXrOptions& options) {
  std::unique_ptr<OpenXrOutput> out(new OpenXrOutput(context, options));
  if (auto connected = out->connect(); !connected) return fail(connected.error());
  return out;
}

void OpenXrOutput::log(const std::string& line) const {
  if (options_.log) options_.log(line);
}

const Lifecycle& OpenXrOutput::lifecycle() const {
  static const Lifecycle none;
  return session_ ? session_->lifecycle() : none;
}

// Instance (unless it survived), EGL binding, session, swapchains: everything a frame needs.
Status OpenXrOutput::connect() {
  if (!instance_) {
    auto instance = Instance::create(options_.instance);
    if (!instance) return fail(instance.error());
    instance_.emplace(instance.take());
    runtime_ = instance_->runtime();
  }
  if (auto current = context_.make_current(); !current) return fail(current.error());
  std::optional<XrGraphicsBindingEGLMNDX> binding;
  if (!instance_->headless()) {
    if (Status can = check_runtime_can_start(runtime_.name, [](const char* n) { return std::getenv(n); }); !can) {
      return can;
    }
    auto b = egl_binding(*instance_, context_);
    if (!b) return fail(b.error());
    binding = *b;
  }
  auto blend = preferred_blend_mode(*instance_);
  if (!blend) return fail(blend.error());
  blend_ = *blend;
  auto session = Session::create(*instance_, binding ? &*binding : nullptr, options_.space, options_.log);
  if (!session) return fail(session.error());
  session_.emplace(session.take());
  if (!instance_->headless()) {
    if (auto made = targets_.create(*instance_, session_->handle()); !made) return made;
  }
  log("OpenXR: " + runtime_.text() + ", " + runtime_.system_name + "; " + std::to_string(targets_.width()) + "x" +
      std::to_string(targets_.height()) + " per view, " + (instance_->headless() ? "headless" : targets_.formats()) +
      ", " + blend_name(blend_) + ", space " +
      (session_->space_type() == XR_REFERENCE_SPACE_TYPE_STAGE ? "STAGE" : "LOCAL"));
  return ok();
}

void OpenXrOutput::disconnect(bool instance_too) {
  // GL names are deleted in the context; the swapchains go before their session.
  if (Status current = context_.make_current(); !current) log("OpenXR: disconnecting: " + current.error());
  targets_.clear();
  session_.reset();
  if (instance_too) instance_.reset();
  begun_ = located_ = false;
}

Status OpenXrOutput::handle(LifecycleAction action) {
  switch (action) {
    case LifecycleAction::DestroySession:
      disconnect(false);
      exited_ = true;
      return ok();
    case LifecycleAction::ReconnectSession:
    case LifecycleAction::ReconnectInstance:
      disconnect(action == LifecycleAction::ReconnectInstance);
      reconnect_at_ns_ = monotonic_ns() + kReconnectEveryNs;
      reconnect_failed_logged_ = false;
      return ok();
    default: return ok();
  }
}

Result<XrFrameTiming> OpenXrOutput::wait_frame() {
  XrFrameTiming timing;
  if (exited_) return timing;
  if (reconnect_at_ns_ >= 0) {
    std::this_thread::sleep_for(kIdleWait);
    if (monotonic_ns() < reconnect_at_ns_) return timing;
    if (auto again = connect(); !again) {
      if (!reconnect_failed_logged_) log(again.error() + "; trying again every 1 s");
      reconnect_failed_logged_ = true;
      disconnect(false);
      reconnect_at_ns_ = monotonic_ns() + kReconnectEveryNs;
      return timing;
    }
    log("OpenXR: reconnected to " + runtime_.text());
    reconnect_at_ns_ = -1;
  }
  auto action = session_->poll_events();
  if (!action) return fail(action.error());
  if (*action != LifecycleAction::None) {
    if (auto handled = handle(*action); !handled) return fail(handled.error());
    return timing;
  }
  // A headless session (XR_MND_headless) has no frames to pace: Monado's xrWaitFrame returns at once for it and
  // its xrBeginFrame then refuses; only the state changes matter.
  if (!session_->lifecycle().running() || instance_->headless()) {
    std::this_thread::sleep_for(kIdleWait);
    return timing;
  }
  frame_ = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
  if (XrResult r = xrWaitFrame(session_->handle(), nullptr, &frame_); XR_FAILED(r)) {
    return fail(xr_error(instance_->handle(), "xrWaitFrame", r));
  }
  if (XrResult r = xrBeginFrame(session_->handle(), nullptr); XR_FAILED(r)) {
    return fail(xr_error(instance_->handle(), "xrBeginFrame", r));
  }
  begun_ = true;
  located_ = false;
  period_ns_ = frame_.predictedDisplayPeriod;
  timing.begun = true;
  timing.should_render = frame_.shouldRender == XR_TRUE && !instance_->headless();
  timing.display_ns = instance_->to_monotonic_ns(frame_.predictedDisplayTime);
  timing.period_ns = frame_.predictedDisplayPeriod;
  return timing;
}

Result<std::span<const render::EyeView>> OpenXrOutput::locate_views(const glm::mat4* world_from_head) {
  located_ = false;
  if (!begun_ || frame_.shouldRender != XR_TRUE || instance_->headless()) return std::span<const render::EyeView>{};
  auto info = xr_struct<XrViewLocateInfo>(XR_TYPE_VIEW_LOCATE_INFO);
  info.viewConfigurationType = Instance::kViewConfiguration;
  info.displayTime = frame_.predictedDisplayTime;
  auto state = xr_struct<XrViewState>(XR_TYPE_VIEW_STATE);
  std::uint32_t count = 0;
  const auto locate = [&](XrSpace space, std::array<XrView, 2>& out) {
    for (auto& v : out) v = xr_struct<XrView>(XR_TYPE_VIEW);
    info.space = space;
    return xrLocateViews(session_->handle(), &info, &state, 2, &count, out.data());
  };
  if (XrResult r = locate(session_->app_space(), views_); XR_FAILED(r)) {
    return fail(xr_error(instance_->handle(), "xrLocateViews", r));
  }
  const XrViewStateFlags needed = XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT;
  if ((state.viewStateFlags & needed) != needed || count != 2) return std::span<const render::EyeView>{};
  if (world_from_head != nullptr) {
    if (XrResult r = locate(session_->view_space(), views_in_head_); XR_FAILED(r)) {
      return fail(xr_error(instance_->handle(), "xrLocateViews(VIEW)", r));
    }
  }
  const render::Viewport viewport{0, 0, targets_.width(), targets_.height()};
  for (std::size_t i = 0; i < 2; ++i) {
    const glm::mat4 world_from_view = world_from_head != nullptr
                                          ? *world_from_head * pose_matrix_mm(views_in_head_[i].pose)
                                          : options_.world_from_space * pose_matrix_mm(views_[i].pose);
    eyes_[i] = eye_view(world_from_view, views_[i].fov, options_.near_mm, options_.far_mm, viewport);
  }
  located_ = true;
  return std::span<const render::EyeView>(eyes_.data(), 2);
}

Status OpenXrOutput::bind_view(std::size_t view) {
  if (!located_) return fail("OpenXR: bind_view: expected located views this frame (locate_views() first)");
  return targets_.bind(view);
}

Status OpenXrOutput::read_view(std::size_t view, std::vector<std::uint8_t>& rgba) {
  if (!located_ || view >= targets_.count()) return fail("OpenXR: read_view: expected a view drawn this frame");
  if (auto bound = targets_.bind(view); !bound) return bound;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets_.framebuffer(view));
  render::read_pixels_top_down(0, 0, targets_.width(), targets_.height(), rgba);
  return ok();
}

Status OpenXrOutput::end_frame() {
  if (!begun_) return ok();
  begun_ = false;
  bool drawn = false;
  if (!instance_->headless()) {
    auto released = targets_.release_all();
    if (!released) return fail(released.error());
    drawn = *released && located_;
  }
  auto layer = xr_struct<XrCompositionLayerProjection>(XR_TYPE_COMPOSITION_LAYER_PROJECTION);
  const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
  auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
  end.displayTime = frame_.predictedDisplayTime;
  end.environmentBlendMode = blend_;
  if (drawn) {
    const auto views = targets_.layer_views(views_, options_.near_mm, options_.far_mm);
    layer.space = session_->app_space();
    layer.viewCount = static_cast<std::uint32_t>(views.size());
    layer.views = views.data();
    end.layerCount = 1;
    end.layers = layers;
  }
  if (XrResult r = xrEndFrame(session_->handle(), &end); XR_FAILED(r)) {
    return fail(xr_error(instance_->handle(), "xrEndFrame", r));
  }
  if (drawn) ++frames_submitted_;
  located_ = false;
  return ok();
}

Status OpenXrOutput::request_exit() {
  if (!session_) {
    exited_ = true;
    return ok();
  }
  if (auto asked = session_->request_exit(); !asked) return asked;
  if (!session_->lifecycle().running()) {
    disconnect(false);
    exited_ = true;
  }
  return ok();
}

}  // namespace lungar::platform::openxr
