/// @file openxr_frame_output.cpp
/// @brief OpenXR behind FrameOutput: settings -> options, pacing, views, per-view targets, snapshot, stats.
#include "platform/output/openxr_frame_output.h"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

#include "config/base/clock.h"
#include "platform/openxr/openxr_output.h"
#include "platform/runtime/gl_math.h"
#include "render/png_snapshot.h"

namespace lungar::platform {
namespace {

// Waiting for the session to run (READY at start, or a reconnection) is done inside begin_frame() for this long at
// most, so that the Runtime neither records empty frames nor stops hearing Ctrl-C.
constexpr std::int64_t kMaxIdleWaitNs = 100'000'000;
// At exit: how long the runtime has to go through STOPPING and EXITING.
constexpr int kMaxExitFrames = 40;

/// The OpenXR options the settings give (reference space, clip planes, the reference space's registration).
openxr::OpenXrOptions openxr_options(const DisplaySettings& display, const HmdSettings& hmd,
                                     const glm::mat4& world_from_space) {
  openxr::OpenXrOptions o;
  o.space = display.openxr.reference_space == XrReferenceSpace::Stage ? XR_REFERENCE_SPACE_TYPE_STAGE
                                                             : XR_REFERENCE_SPACE_TYPE_LOCAL;
  o.near_mm = static_cast<float>(hmd.near_mm);
  o.far_mm = static_cast<float>(hmd.far_mm);
  o.world_from_space = world_from_space;
  return o;
}

}  // namespace

OpenXrFrameOutput::OpenXrFrameOutput(std::unique_ptr<EglContext> context, bool tracker_head)
    : context_(std::move(context)), tracker_head_(tracker_head) {}

Result<std::unique_ptr<OpenXrFrameOutput>> OpenXrFrameOutput::create(const DisplaySettings& display,
                                                                     const HmdSettings& hmd,
                                                                     const glm::mat4& world_from_space,
                                                                     std::function<void(const std::string&)> log) {
  auto context = EglContext::headless();
  if (!context) return context.with_context("display: ");
  std::unique_ptr<OpenXrFrameOutput> out(new OpenXrFrameOutput(context.take(), display.openxr.head == XrHead::Tracker));
  openxr::OpenXrOptions options = openxr_options(display, hmd, world_from_space);
  options.log = log;
  auto xr = openxr::OpenXrOutput::create(*out->context_, options);
  if (!xr) return xr.with_context("display.output = \"openxr\": ");
  out->xr_ = xr.take();
  out->views_.shared_target = false;
  if (hmd.lens.enabled && log) log("hmd.lens: not used with OpenXR (the runtime corrects its own lenses)");
  return out;
}

OpenXrFrameOutput::~OpenXrFrameOutput() {
  if (!xr_ || xr_->exited()) return;
  if (Status asked = xr_->request_exit(); !asked) return;
  for (int i = 0; i < kMaxExitFrames && !xr_->exited(); ++i) {
    auto timing = xr_->wait_frame();
    if (!timing || !xr_->end_frame()) return;
  }
}

bool OpenXrFrameOutput::poll_events() { return !xr_->exited(); }

std::array<int, 2> OpenXrFrameOutput::target_size() const { return {xr_->view_width(), xr_->view_height()}; }

std::string OpenXrFrameOutput::describe() const {
  const openxr::RuntimeInfo& r = xr_->runtime();
  return context_->describe() + " (OpenXR: " + r.text() + ", " + r.system_name + ", " +
         std::to_string(xr_->view_width()) + "x" + std::to_string(xr_->view_height()) + " per view, " +
         xr_->formats() + ", head from " + (tracker_head_ ? "lungar's tracker" : "the runtime") + ")";
}

Result<FrameTiming> OpenXrFrameOutput::begin_frame(std::int64_t now_ns) {
  bind_error_.clear();
  for (;;) {
    auto timing = xr_->wait_frame();
    if (!timing) return timing.with_context("");
    if (timing->begun) return FrameTiming{timing->display_ns, timing->should_render};
    if (xr_->exited() || monotonic_ns() - now_ns > kMaxIdleWaitNs) return FrameTiming{0, false};
  }
}

const FrameViews& OpenXrFrameOutput::views(const glm::mat4& head_to_world) {
  auto eyes = xr_->locate_views(tracker_head_ ? &head_to_world : nullptr);
  views_.count = 0;
  if (!eyes) {
    bind_error_ = eyes.error();
    return views_;
  }
  std::copy(eyes->begin(), eyes->end(), views_.eyes.begin());
  views_.count = eyes->size();
  return views_;
}

void OpenXrFrameOutput::bind_target(std::size_t i) {
  if (Status bound = xr_->bind_view(i); !bound && bind_error_.empty()) bind_error_ = bound.error();
}

Status OpenXrFrameOutput::end_frame() {
  Status ended = xr_->end_frame();
  if (!bind_error_.empty()) return fail(std::exchange(bind_error_, {}));
  return ended;
}

Status OpenXrFrameOutput::snapshot(const std::string& png_path) {
  const int w = xr_->view_width(), h = xr_->view_height();
  const auto row = static_cast<std::size_t>(w) * 4;
  side_by_side_.assign(row * 2 * static_cast<std::size_t>(h), 0);
  for (std::size_t v = 0; v < 2; ++v) {
    if (Status read = xr_->read_view(v, view_pixels_); !read) return read;
    for (int y = 0; y < h; ++y) {
      std::memcpy(&side_by_side_[static_cast<std::size_t>(y) * 2 * row + v * row],
                  &view_pixels_[static_cast<std::size_t>(y) * row], row);
    }
  }
  return render::write_png(png_path, 2 * w, h, side_by_side_);
}

void OpenXrFrameOutput::add_stats(nlohmann::json& stats) const {
  stats["xr_runtime"] = xr_->runtime().text();
  stats["xr_frames_submitted"] = xr_->frames_submitted();
  stats["xr_predicted_display_period_ms"] = xr_->predicted_display_period_ms();
}

}  // namespace lungar::platform
