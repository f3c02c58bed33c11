/// @file frame_output.h
/// @brief Where a frame goes, behind one small interface (as Filament hides its backend and Monado its
/// compositor targets): a headless framebuffer, an X11 window, an OpenXR session. The Runtime asks it for the
/// frame's pacing and views, draws into the targets it binds, and hands the frame back to it; nothing in the
/// frame knows which output it draws for.
/// @ingroup platform
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include <glm/mat4x4.hpp>
#include <nlohmann/json_fwd.hpp>

#include "config/base/result.h"
#include "render/stereo_view.h"

namespace lungar::platform {

/// The views of one frame and where each is drawn.
struct FrameViews {
  std::array<render::EyeView, 2> eyes{};  ///< left then right, or the single mono view
  std::size_t count = 0;
  /// True: every view is a viewport of one framebuffer, target 0 (side by side). False: view i has its own
  /// framebuffer, target i (an OpenXR swapchain image per view).
  bool shared_target = true;
  std::span<const render::EyeView> span() const { return {eyes.data(), count}; }
};

/// When the frame being started will be shown, and whether it is to be drawn at all.
struct FrameTiming {
  std::int64_t display_ns = 0;  ///< predicted display time (monotonic); 0: the output does not know
  bool should_render = true;    ///< false: submit an empty frame (an OpenXR session not yet visible)
};

class FrameOutput {
 public:
  virtual ~FrameOutput() = default;
  /// One line for the start-up log: kind, size, EGL and GL renderer.
  virtual std::string describe() const = 0;
  /// Handles pending events; false once the output is closed (window closed, Escape, session ending).
  virtual bool poll_events() = 0;
  /// The keys pressed since the last call: lower-case letters, and Space, Enter, Backspace as ' ', '\n', '\b' (an
  /// output without a keyboard: none).
  virtual std::string take_keys() { return {}; }
  /// Waits for the output's pacing (a no-op where the swap interval paces) and says when the frame is shown.
  virtual Result<FrameTiming> begin_frame(std::int64_t now_ns) = 0;
  /// The views of this frame. `head_to_world` is the tracker's head pose predicted to display time (OpenGL
  /// camera convention: +y up, looking down -z, mm); an output that tracks the head itself may ignore it.
  virtual const FrameViews& views(const glm::mat4& head_to_world) = 0;
  /// Binds target `i` as the draw framebuffer (see FrameViews::shared_target).
  virtual void bind_target(std::size_t i) = 0;
  /// The scene of this frame is drawn, the overlays are not: an output with a lens pass warps the scene into its
  /// own framebuffer now, and leaves that bound.
  virtual Status finish_scene(const FrameViews& views) {
    (void)views;
    return ok();
  }
  /// Width and height of target 0 in pixels.
  virtual std::array<int, 2> target_size() const = 0;
  /// Hands the frame over: swap, finish, or xrEndFrame.
  virtual Status end_frame() = 0;
  /// Writes the last frame (target 0) as a PNG.
  virtual Status snapshot(const std::string& png_path) = 0;
  /// Adds this output's keys to the stats JSON.
  virtual void add_stats(nlohmann::json& stats) const { (void)stats; }
};

}  // namespace lungar::platform
