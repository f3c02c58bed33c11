/// @file scissor_fill.cpp
/// @brief The scissored clears of scissor_fill.h.
#include "render/scissor_fill.h"

#include <GLES3/gl3.h>

#include <algorithm>

namespace lungar::render {

ScissorFill::ScissorFill() {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_SCISSOR_TEST);
  colour({0.f, 0.f, 0.f});
}

ScissorFill::~ScissorFill() { glDisable(GL_SCISSOR_TEST); }

void ScissorFill::colour(const std::array<float, 3>& rgb) { glClearColor(rgb[0], rgb[1], rgb[2], 1.f); }

void ScissorFill::fill(const Viewport& rect, const Viewport& clip) const {
  const int x0 = std::max(rect.x, clip.x), y0 = std::max(rect.y, clip.y);
  const int x1 = std::min(rect.x + rect.width, clip.x + clip.width);
  const int y1 = std::min(rect.y + rect.height, clip.y + clip.height);
  if (x1 <= x0 || y1 <= y0) return;
  glScissor(x0, y0, x1 - x0, y1 - y0);
  glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace lungar::render
