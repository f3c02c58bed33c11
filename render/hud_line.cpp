/// @file hud_line.cpp
/// @brief The 3x5 font and the blit of the status line.
#include "render/hud_line.h"

#include <GLES3/gl3.h>

#include <cctype>
#include <cstring>

namespace lungar::render {

namespace {

/// Rows of 3 bits, top first: r0..r4 -> one 15-bit glyph.
constexpr std::uint16_t rows(int r0, int r1, int r2, int r3, int r4) {
  return static_cast<std::uint16_t>((r0 << 12) | (r1 << 9) | (r2 << 6) | (r3 << 3) | r4);
}

struct Glyph {
  char c;
  std::uint16_t bits;
};

// The glyphs, written as binary rows (0b101 = pixel, gap, pixel).
constexpr Glyph kFont[] = {
    {'0', rows(0b111, 0b101, 0b101, 0b101, 0b111)}, {'1', rows(0b010, 0b110, 0b010, 0b010, 0b111)},
    {'2', rows(0b111, 0b001, 0b111, 0b100, 0b111)}, {'3', rows(0b111, 0b001, 0b111, 0b001, 0b111)},
    {'4', rows(0b101, 0b101, 0b111, 0b001, 0b001)}, {'5', rows(0b111, 0b100, 0b111, 0b001, 0b111)},
    {'6', rows(0b111, 0b100, 0b111, 0b101, 0b111)}, {'7', rows(0b111, 0b001, 0b001, 0b001, 0b001)},
    {'8', rows(0b111, 0b101, 0b111, 0b101, 0b111)}, {'9', rows(0b111, 0b101, 0b111, 0b001, 0b111)},
    {'A', rows(0b010, 0b101, 0b111, 0b101, 0b101)}, {'B', rows(0b110, 0b101, 0b110, 0b101, 0b110)},
    {'C', rows(0b011, 0b100, 0b100, 0b100, 0b011)}, {'D', rows(0b110, 0b101, 0b101, 0b101, 0b110)},
    {'E', rows(0b111, 0b100, 0b110, 0b100, 0b111)}, {'F', rows(0b111, 0b100, 0b110, 0b100, 0b100)},
    {'G', rows(0b011, 0b100, 0b101, 0b101, 0b011)}, {'H', rows(0b101, 0b101, 0b111, 0b101, 0b101)},
    {'I', rows(0b111, 0b010, 0b010, 0b010, 0b111)}, {'J', rows(0b001, 0b001, 0b001, 0b101, 0b010)},
    {'K', rows(0b101, 0b101, 0b110, 0b101, 0b101)}, {'L', rows(0b100, 0b100, 0b100, 0b100, 0b111)},
    {'M', rows(0b101, 0b111, 0b111, 0b101, 0b101)}, {'N', rows(0b110, 0b101, 0b101, 0b101, 0b101)},
    {'O', rows(0b010, 0b101, 0b101, 0b101, 0b010)}, {'P', rows(0b110, 0b101, 0b110, 0b100, 0b100)},
    {'Q', rows(0b010, 0b101, 0b101, 0b110, 0b011)}, {'R', rows(0b110, 0b101, 0b110, 0b101, 0b101)},
    {'S', rows(0b011, 0b100, 0b010, 0b001, 0b110)}, {'T', rows(0b111, 0b010, 0b010, 0b010, 0b010)},
    {'U', rows(0b101, 0b101, 0b101, 0b101, 0b111)}, {'V', rows(0b101, 0b101, 0b101, 0b101, 0b010)},
    {'W', rows(0b101, 0b101, 0b111, 0b111, 0b101)}, {'X', rows(0b101, 0b101, 0b010, 0b101, 0b101)},
    {'Y', rows(0b101, 0b101, 0b010, 0b010, 0b010)}, {'Z', rows(0b111, 0b001, 0b010, 0b100, 0b111)},
    {'.', rows(0b000, 0b000, 0b000, 0b000, 0b010)}, {':', rows(0b000, 0b010, 0b000, 0b010, 0b000)},
    {'/', rows(0b001, 0b001, 0b010, 0b100, 0b100)}, {'-', rows(0b000, 0b000, 0b111, 0b000, 0b000)},
    {'%', rows(0b101, 0b001, 0b010, 0b100, 0b101)}, {'(', rows(0b010, 0b100, 0b100, 0b100, 0b010)},
    {')', rows(0b010, 0b001, 0b001, 0b001, 0b010)}, {',', rows(0b000, 0b000, 0b000, 0b010, 0b100)},
    {'=', rows(0b000, 0b111, 0b000, 0b111, 0b000)}, {'+', rows(0b000, 0b010, 0b111, 0b010, 0b000)},
};

constexpr std::uint8_t kText[4] = {120, 255, 120, 255};  // green: readable on the see-through black
constexpr std::uint8_t kBack[4] = {0, 0, 0, 255};

}  // namespace

std::uint16_t HudLine::glyph(char c) {
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kFont) {
    if (g.c == u) return g.bits;
  }
  return 0;
}

HudLine::HudLine() : texture_(gl::Texture::create()), framebuffer_(gl::Framebuffer::create()) {
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kMaxChars * kCellW, kCellH);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
}

void HudLine::set_text(std::string_view text) {
  const int n = static_cast<int>(std::min<std::size_t>(text.size(), kMaxChars));
  if (n == chars_ && std::memcmp(text_.data(), text.data(), static_cast<std::size_t>(n)) == 0) return;
  chars_ = n;
  std::memcpy(text_.data(), text.data(), static_cast<std::size_t>(n));
  const int stride = kMaxChars * kCellW;
  for (int y = 0; y < kCellH; ++y) {
    for (int x = 0; x < n * kCellW; ++x) {
      const int cell = x / kCellW, gx = x % kCellW - 1, gy = y - 1;  // one-pixel border left and top
      const std::uint16_t bits = glyph(text_[static_cast<std::size_t>(cell)]);
      const bool on = gx >= 0 && gx < 3 && gy >= 0 && gy < 5 && ((bits >> (14 - (gy * 3 + gx))) & 1u);
      std::memcpy(&pixels_[static_cast<std::size_t>((y * stride + x) * 4)], on ? kText : kBack, 4);
    }
  }
  if (n == 0) return;
  // GL's texture rows go bottom-up: upload the top row last.
  glBindTexture(GL_TEXTURE_2D, texture_.id());
  glPixelStorei(GL_UNPACK_ROW_LENGTH, stride);
  for (int y = 0; y < kCellH; ++y) {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, kCellH - 1 - y, n * kCellW, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                    &pixels_[static_cast<std::size_t>(y * stride * 4)]);
  }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void HudLine::draw(const Viewport& viewport, int scale) const { draw_at(viewport, 4, viewport.height - 4, scale); }

void HudLine::draw_at(const Viewport& viewport, int left_px, int top_px, int scale) const {
  if (chars_ == 0) return;
  GLint read = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  const int w = std::min(chars_ * kCellW * scale, viewport.width - 2 * left_px);
  const int top = viewport.y + top_px, left = viewport.x + left_px;
  glBlitFramebuffer(0, 0, w / scale, kCellH, left, top - kCellH * scale, left + w, top, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
}

}  // namespace lungar::render
