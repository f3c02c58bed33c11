/// @file hud_line.h
/// @brief One line of status text (frame rate, pose age, tracker state) over a viewport: a 3x5 pixel font
/// rasterised on the CPU into a small texture and blitted, scaled, into the frame. No shader, no allocation per
/// frame; the text is re-rasterised only when it changes.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "render/gl_objects.h"
#include "render/stereo_view.h"

namespace lungar::render {

class HudLine {
 public:
  static constexpr int kMaxChars = 96;
  static constexpr int kCellW = 4, kCellH = 7;  ///< glyph 3x5 plus spacing and a one-pixel border

  /// Needs a current GLES 3 context.
  HudLine();
  /// Sets the text (upper-cased; characters without a glyph show as blanks; cut at kMaxChars).
  void set_text(std::string_view text);
  /// Blits the line into the top-left corner of `viewport` of the bound draw framebuffer, `scale` screen
  /// pixels per font pixel. The draw framebuffer binding is restored.
  void draw(const Viewport& viewport, int scale = 2) const;
  /// The same with the line's top `top_px` above the viewport's bottom edge and its left `left_px` right of its left.
  void draw_at(const Viewport& viewport, int left_px, int top_px, int scale = 2) const;
  /// The rasterised line (for tests): kMaxChars * kCellW by kCellH RGBA pixels, top row first; `width()` used.
  const std::uint8_t* pixels() const { return pixels_.data(); }
  int width() const { return chars_ * kCellW; }

  /// The 3x5 glyph of `c` as 15 bits, row-major from the top-left (0 for a blank or unknown character).
  static std::uint16_t glyph(char c);

 private:
  std::array<std::uint8_t, kMaxChars * kCellW * kCellH * 4> pixels_{};
  std::array<char, kMaxChars> text_{};
  int chars_ = 0;
  gl::Texture texture_;
  gl::Framebuffer framebuffer_;
};

}  // namespace lungar::render
