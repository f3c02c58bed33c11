/// @file lens_distortion.h
/// @brief The optional HMD lens pre-distortion pass: radial k1, k2 per colour channel (chromatic aberration),
/// sampling an undistorted FrameTarget and drawing each eye into the bound framebuffer.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "config/base/result.h"
#include "render/frame_target.h"
#include "render/gl_objects.h"
#include "render/stereo_view.h"

namespace lungar::render {

/// r_src = r (1 + k1 r^2 + k2 r^4), r from the lens centre in units of the eye's half height.
struct LensParams {
  std::array<float, 3> k1{0.22f, 0.24f, 0.26f};  ///< R, G, B
  std::array<float, 3> k2{0.24f, 0.26f, 0.28f};
};

/// Where the lens axis meets an eye's image, in its 0..1 coordinates: the projection's axis for an off-axis frustum.
std::array<float, 2> lens_centre(const HmdGeometry& hmd, bool left);

class LensDistortion {
 public:
  static Result<LensDistortion> create();
  /// Draws `eyes` (viewports of `source`, the same viewports in the bound framebuffer) distorted; `centres` holds
  /// one lens centre per eye.
  Status apply(const FrameTarget& source, std::span<const EyeView> eyes, std::span<const std::array<float, 2>> centres,
               const LensParams& params) const;

 private:
  LensDistortion() = default;
  gl::Program program_;
  gl::VertexArray empty_vao_;  // the full-screen triangle comes from gl_VertexID
  std::int32_t image_ = -1, rect_ = -1, centre_ = -1, aspect_ = -1, k1_ = -1, k2_ = -1;
};

}  // namespace lungar::render
