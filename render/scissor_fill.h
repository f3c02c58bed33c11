/// @file scissor_fill.h
/// @brief Solid rectangles in the bound draw framebuffer by scissored clears: no shader, nothing to compile, so a
/// screen of plain shapes (the SPAAM crosshair) draws on any context that can clear.
#pragma once

#include <array>

#include "render/stereo_view.h"

namespace lungar::render {

class ScissorFill {
 public:
  /// Turns depth testing and blending off and the scissor test on, for as long as the fill lives; needs a current
  /// GLES 3 context. The clear colour starts black.
  ScissorFill();
  /// Turns the scissor test off again.
  ~ScissorFill();
  ScissorFill(const ScissorFill&) = delete;
  ScissorFill& operator=(const ScissorFill&) = delete;

  /// The colour of the following fills (opaque).
  void colour(const std::array<float, 3>& rgb);
  /// Fills the rectangle (GL's pixels, from the bottom-left) clipped to `clip`.
  void fill(const Viewport& rect, const Viewport& clip) const;
};

}  // namespace lungar::render
