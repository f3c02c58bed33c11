/// @file lesion_drawable.h
/// @brief Lesions (tumours) drawn inside the lungs: each a lit ball in its own colour at its centre for this frame,
///        for one or two eyes, over the lungs whatever their draw mode.
///
/// Over, not among: the depth test is off for the lesion (its back faces culled, so the ball stays a ball), so it
/// shows through the lungs' points and through a mesh alike. A trainee looking for the tumour must not lose it
/// behind the lung's near surface; the lungs drawn around it say where in the lung it is, and the two eyes'
/// disparity how deep.
#pragma once

#include <cstdint>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "config/base/result.h"
#include "render/gl_objects.h"
#include "render/stereo_view.h"

namespace lungar::render {

/// One lesion this frame.
struct LesionFrame {
  glm::vec3 centre_mm{0.f};  ///< moved by the interior field, lung frame
  float radius_mm = 5.f;
  glm::vec3 color{1.0f, 0.85f, 0.1f};
  glm::mat4 rest_transform{1.f};  ///< its lung's (render/renderer.h, LungFrame::rest_transform)
};

class LesionDrawable {
 public:
  /// Builds the program and the unit sphere's buffers; needs a current GLES 3 context.
  static Result<LesionDrawable> create();

  /// Draws every lesion for every eye into the bound framebuffer (`model`: lung frame -> world). GL state it
  /// changes (depth test, face culling, program, vertex array) is left as the renderer expects: depth test on,
  /// culling off.
  void draw(std::span<const LesionFrame> lesions, const glm::mat4& model, std::span<const EyeView> eyes,
            float ambient = 0.3f) const;

  std::uint32_t triangles() const { return index_count_ / 3; }

 private:
  LesionDrawable() = default;
  gl::Program program_;
  gl::Buffer vertices_, indices_;
  gl::VertexArray vao_;
  std::uint32_t index_count_ = 0;
  std::int32_t mvp_ = -1, eye_ = -1, centre_ = -1, radius_ = -1, color_ = -1, ambient_ = -1;
};

}  // namespace lungar::render
