/// @file lens_distortion.cpp
/// @brief The lens pass: one full-viewport triangle per eye through lens.frag.
#include "render/lens_distortion.h"

#include <GLES3/gl3.h>

#include <cmath>

#include "lungar/render/shaders.h"
#include "render/shader_program.h"

namespace lungar::render {

std::array<float, 2> lens_centre(const HmdGeometry& hmd, bool left) {
  const double inner = std::tan(hmd.fov_inner_deg * M_PI / 180.0), outer = std::tan(hmd.fov_outer_deg * M_PI / 180.0);
  const double up = std::tan(hmd.fov_up_deg * M_PI / 180.0), down = std::tan(hmd.fov_down_deg * M_PI / 180.0);
  const double x = left ? outer / (outer + inner) : inner / (outer + inner);
  return {static_cast<float>(x), static_cast<float>(down / (up + down))};
}

Result<LensDistortion> LensDistortion::create() {
  ProgramSource src;
  src.name = "lens.vert+lens.frag";
  src.vertex = shaders::lens_vert;
  src.fragment = shaders::lens_frag;
  auto program = build_program(src);
  if (!program) return fail(program.error());
  LensDistortion d;
  d.program_ = program.take();
  d.empty_vao_ = gl::VertexArray::create();
  d.program_.find_uniforms({{&d.image_, "u_eye_image"}, {&d.rect_, "u_eye_rect"}, {&d.centre_, "u_center"},
                            {&d.aspect_, "u_aspect"}, {&d.k1_, "u_k1"}, {&d.k2_, "u_k2"}});
  return d;
}

Status LensDistortion::apply(const FrameTarget& source, std::span<const EyeView> eyes,
                             std::span<const std::array<float, 2>> centres, const LensParams& p) const {
  if (eyes.size() != centres.size() || eyes.empty()) {
    return fail("lens distortion: centres: expected one per eye (" + std::to_string(eyes.size()) + "), got " +
            std::to_string(centres.size()));
  }
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program_.id());
  glBindVertexArray(empty_vao_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source.color_texture());
  glUniform1i(image_, 0);
  glUniform3f(k1_, p.k1[0], p.k1[1], p.k1[2]);
  glUniform3f(k2_, p.k2[0], p.k2[1], p.k2[2]);
  const float w = static_cast<float>(source.width()), h = static_cast<float>(source.height());
  for (std::size_t e = 0; e < eyes.size(); ++e) {
    const Viewport& v = eyes[e].viewport;
    glViewport(v.x, v.y, v.width, v.height);
    glUniform4f(rect_, static_cast<float>(v.x) / w, static_cast<float>(v.y) / h, static_cast<float>(v.width) / w,
                static_cast<float>(v.height) / h);
    glUniform2f(centre_, centres[e][0], centres[e][1]);
    glUniform1f(aspect_, static_cast<float>(v.width) / static_cast<float>(v.height));
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  return ok();
}

}  // namespace lungar::render
