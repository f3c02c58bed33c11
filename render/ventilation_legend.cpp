/// @file ventilation_legend.cpp
/// @brief The legend's ramp texture, its label and the blits.
#include "render/ventilation_legend.h"

#include <GLES3/gl3.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "render/ventilation_ramp.h"

namespace lungar::render {

VentilationLegend::VentilationLegend(float full_scale_mm)
    : ramp_(gl::Texture::create()), framebuffer_(gl::Framebuffer::create()) {
  std::array<std::uint8_t, kRampTexels * 4> texels{};
  for (int i = 0; i < kRampTexels; ++i) {
    const std::array<float, 3> c = ventilation_colour(static_cast<float>(i) / (kRampTexels - 1));
    for (int k = 0; k < 3; ++k) texels[static_cast<std::size_t>(4 * i + k)] = static_cast<std::uint8_t>(std::lround(255.f * c[k]));
    texels[static_cast<std::size_t>(4 * i + 3)] = 255;
  }
  glBindTexture(GL_TEXTURE_2D, ramp_.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kRampTexels, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kRampTexels, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ramp_.id(), 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
  const long mm = std::lround(full_scale_mm);
  label_.set_text("ventilation 0-" + std::to_string(mm) + " mm/breath");
}

void VentilationLegend::draw(const Viewport& viewport, int scale) const {
  const int bar_w = kRampTexels * scale * 2, bar_h = 5 * scale, left = 8, bottom = 8;
  GLint read = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  const int x0 = viewport.x + left, y0 = viewport.y + bottom;
  glBlitFramebuffer(0, 0, kRampTexels, 1, x0, y0, x0 + std::min(bar_w, viewport.width - 2 * left), y0 + bar_h,
                    GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
  label_.draw_at(viewport, left, bottom + bar_h + 2 + HudLine::kCellH * scale, scale);
}

}  // namespace lungar::render
