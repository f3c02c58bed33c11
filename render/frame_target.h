/// @file frame_target.h
/// @brief An off-screen framebuffer (RGBA8 colour texture + 24-bit depth) to render into headless, to feed the
/// lens-distortion pass, and to read back for PNG snapshots.
#pragma once

#include <cstdint>
#include <vector>

#include "config/base/result.h"
#include "render/gl_objects.h"

namespace lungar::render {

class FrameTarget {
 public:
  /// Needs a current GLES 3 context; fails when the framebuffer is incomplete.
  static Result<FrameTarget> create(int width_px, int height_px);

  void bind() const;  ///< as the draw and read framebuffer, viewport on the whole target
  int width() const { return width_; }
  int height() const { return height_; }
  std::uint32_t framebuffer() const { return framebuffer_.id(); }
  std::uint32_t color_texture() const { return color_.id(); }

 private:
  FrameTarget() = default;
  int width_ = 0, height_ = 0;
  gl::Framebuffer framebuffer_;
  gl::Texture color_;
  gl::Renderbuffer depth_;
};

/// Reads an RGBA8 rectangle of the bound read framebuffer, top row first (the order of PNG files).
void read_pixels_top_down(int x, int y, int width, int height, std::vector<std::uint8_t>& rgba);

}  // namespace lungar::render
