/// @file frame_target.cpp
/// @brief Off-screen framebuffer set-up and read-back.
#include "render/frame_target.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <string>

namespace lungar::render {

Result<FrameTarget> FrameTarget::create(int width_px, int height_px) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width_px <= 0 || height_px <= 0 || width_px > max_size || height_px > max_size) {
    return fail("frame target: size: expected 1.." + std::to_string(max_size) +
                                          " pixels a side, got " + std::to_string(width_px) + "x" +
                                          std::to_string(height_px));
  }
  FrameTarget t;
  t.width_ = width_px;
  t.height_ = height_px;
  t.color_ = gl::Texture::create();
  glBindTexture(GL_TEXTURE_2D, t.color_.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width_px, height_px);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // the lens pass samples between pixels
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  t.depth_ = gl::Renderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_px, height_px);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  t.framebuffer_ = gl::Framebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_.id());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    return fail("frame target: framebuffer incomplete (status " + std::to_string(status) + ")");
  }
  glViewport(0, 0, width_px, height_px);
  return t;
}

void FrameTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

void read_pixels_top_down(int x, int y, int width, int height, std::vector<std::uint8_t>& rgba) {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  rgba.resize(row * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  // GL's rows run bottom-up.
  for (int r = 0; r < height / 2; ++r) {
    std::swap_ranges(rgba.begin() + static_cast<std::ptrdiff_t>(r * row),
                     rgba.begin() + static_cast<std::ptrdiff_t>((r + 1) * row),
                     rgba.begin() + static_cast<std::ptrdiff_t>((height - 1 - r) * row));
  }
}

}  // namespace lungar::render
