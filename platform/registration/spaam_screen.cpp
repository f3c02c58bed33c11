/// @file spaam_screen.cpp
/// @brief The crosshair and the prompt by scissored clears and the status line (spaam_screen.h).
#include "platform/registration/spaam_screen.h"

#include <algorithm>
#include <cmath>

#include "render/scissor_fill.h"

namespace lungar::platform {

namespace {

/// One pixel wide within kCrosshairFinePx of the centre (the point to aim at stays one pixel), three outside it.
void crosshair(const render::ScissorFill& fill, const Eigen::Vector2i& c, const render::Viewport& clip) {
  constexpr int a = kCrosshairArmPx, f = kCrosshairFinePx;
  fill.fill({c.x() - f, c.y(), 2 * f + 1, 1}, clip);
  fill.fill({c.x(), c.y() - f, 1, 2 * f + 1}, clip);
  fill.fill({c.x() - a, c.y() - 1, a - f, 3}, clip);
  fill.fill({c.x() + f + 1, c.y() - 1, a - f, 3}, clip);
  fill.fill({c.x() - 1, c.y() - a, 3, a - f}, clip);
  fill.fill({c.x() - 1, c.y() + f + 1, 3, a - f}, clip);
}

}  // namespace

Eigen::Vector2i spaam_framebuffer_pixel(const render::Viewport& viewport, int eye_width_px, int eye_height_px,
                                        const Eigen::Vector2d& pixel) {
  const int column = static_cast<int>(std::floor(pixel.x() * viewport.width / eye_width_px));
  const int row_from_top = static_cast<int>(std::floor(pixel.y() * viewport.height / eye_height_px));
  return {viewport.x + column, viewport.y + viewport.height - 1 - row_from_top};
}

void SpaamScreen::draw(const std::array<render::Viewport, 2>& viewports, int eye, int eye_width_px, int eye_height_px,
                       const Eigen::Vector2d& pixel, const std::array<std::string, 4>& lines) {
  const render::Viewport& v = viewports[static_cast<std::size_t>(eye)];
  {
    render::ScissorFill fill;  // black, then the crosshair in green
    for (const render::Viewport& each : viewports) fill.fill(each, each);
    fill.colour({0.f, 1.f, 0.f});
    crosshair(fill, spaam_framebuffer_pixel(v, eye_width_px, eye_height_px, pixel), v);
  }
  std::size_t longest = 0;
  for (const std::string& line : lines) longest = std::max(longest, line.size());
  const int scale = static_cast<int>(longest) * render::HudLine::kCellW * 2 + 8 <= v.width ? 2 : 1;
  int top = v.height - 4;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    text_[i].set_text(lines[i]);
    text_[i].draw_at(v, 4, top, scale);
    top -= render::HudLine::kCellH * scale + 2;
  }
}

}  // namespace lungar::platform
