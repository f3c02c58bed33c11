/// @file ventilation_legend.h
/// @brief The ventilation map's legend: the colour ramp as a bar in the bottom-left corner of a view, with its
///        label and scale above it ("VENTILATION 0-12 MM/BREATH"), blitted like the status line (no shader).
#pragma once

#include "render/gl_objects.h"
#include "render/hud_line.h"
#include "render/stereo_view.h"

namespace lungar::render {

class VentilationLegend {
 public:
  static constexpr int kRampTexels = 64;

  /// Needs a current GLES 3 context; `full_scale_mm` is the sweep at the ramp's top, written in the label.
  explicit VentilationLegend(float full_scale_mm);
  /// Blits the bar and its label into the bottom-left corner of `viewport` of the bound draw framebuffer.
  void draw(const Viewport& viewport, int scale = 2) const;

 private:
  HudLine label_;
  gl::Texture ramp_;
  gl::Framebuffer framebuffer_;
};

}  // namespace lungar::render
