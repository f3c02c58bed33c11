/// @file spaam_screen.h
/// @brief One frame of the SPAAM screen: black everywhere (an optical see-through display shows black as
///        nothing, so the other eye sees only the room), a green crosshair in the calibrated eye's viewport and
///        the prompt over it. Scissored clears and the status line's blit: no shader, nothing to compile.
#pragma once

#include <array>
#include <string>

#include <Eigen/Core>

#include "render/hud_line.h"
#include "render/stereo_view.h"

namespace lungar::platform {

/// The crosshair's half length and the thin centre's half length, in framebuffer pixels.
inline constexpr int kCrosshairArmPx = 40, kCrosshairFinePx = 10;

/// The framebuffer pixel (from the bottom-left, GL's way) that holds `pixel`, a point of an `eye_width_px` x
/// `eye_height_px` eye panel (origin top-left), when the eye is drawn into `viewport`.
Eigen::Vector2i spaam_framebuffer_pixel(const render::Viewport& viewport, int eye_width_px, int eye_height_px,
                                        const Eigen::Vector2d& pixel);

class SpaamScreen {
 public:
  /// Needs a current GLES 3 context.
  SpaamScreen() = default;

  /// Into the bound draw framebuffer: clears `viewports` (left, right) to black, then draws the crosshair at
  /// `pixel` of eye `eye`'s panel and `lines` (empty ones skipped) at the top of that eye's viewport.
  void draw(const std::array<render::Viewport, 2>& viewports, int eye, int eye_width_px, int eye_height_px,
            const Eigen::Vector2d& pixel, const std::array<std::string, 4>& lines);

 private:
  std::array<render::HudLine, 4> text_;
};

}  // namespace lungar::platform
