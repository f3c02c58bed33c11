/// @file openxr_frame_output.h
/// @brief The Runtime's frames on an OpenXR headset (display.output = "openxr"): the FrameOutput face of
/// openxr::OpenXrOutput. xrWaitFrame paces the frame and says when it is shown; the views are the runtime's
/// (display.openxr.head = "openxr", placed in the world by registration.xr_space_*) or lungar's head tracker's
/// with the runtime's eye offsets ("tracker"); each view has its own target, a swapchain image.
/// The OpenXR back-end stays behind this header (forward-declared, its headers bring EGL and GLES): the wiring that
/// picks the output sees only a FrameOutput.
/// @ingroup platform
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "platform/egl/egl_context.h"
#include "platform/output/output_settings.h"
#include "platform/runtime/frame_output.h"

namespace lungar::platform {

namespace openxr {
class OpenXrOutput;
}

class OpenXrFrameOutput final : public FrameOutput {
 public:
  /// A surfaceless GLES 3 context handed to the runtime; the session, its swapchains. `log` hears the session's
  /// lines (state changes, reconnections).
  /// `world_from_space`: the reference space's pose in the tracker world ([registration] xr_space_*).
  static Result<std::unique_ptr<OpenXrFrameOutput>> create(const DisplaySettings& display, const HmdSettings& hmd,
                                                           const glm::mat4& world_from_space,
                                                           std::function<void(const std::string&)> log);
  /// Asks the runtime to end the session and waits (a little) for EXITING: a clean goodbye.
  ~OpenXrFrameOutput() override;

  std::string describe() const override;
  bool poll_events() override;
  Result<FrameTiming> begin_frame(std::int64_t now_ns) override;
  const FrameViews& views(const glm::mat4& head_to_world) override;
  void bind_target(std::size_t i) override;
  std::array<int, 2> target_size() const override;
  Status end_frame() override;
  /// Both views side by side, as the headless output's stereo snapshot.
  Status snapshot(const std::string& png_path) override;
  void add_stats(nlohmann::json& stats) const override;

  openxr::OpenXrOutput& xr() { return *xr_; }

 private:
  OpenXrFrameOutput(std::unique_ptr<EglContext> context, bool tracker_head);
  std::unique_ptr<EglContext> context_;
  std::unique_ptr<openxr::OpenXrOutput> xr_;
  bool tracker_head_ = false;
  FrameViews views_;
  std::string bind_error_;  ///< bind_target() cannot fail in place: its error comes out of end_frame()
  std::vector<std::uint8_t> view_pixels_, side_by_side_;
};

}  // namespace lungar::platform
