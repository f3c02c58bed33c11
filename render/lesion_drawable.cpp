/// @file lesion_drawable.cpp
/// @brief The lesion's program and unit sphere (latitude-longitude, outward counter-clockwise triangles), and its draw.
#include "render/lesion_drawable.h"

#include <GLES3/gl3.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "lungar/render/shaders.h"
#include "render/shader_program.h"

namespace lungar::render {

namespace {

constexpr int kRings = 12, kSegments = 24;  // about 4 px a facet for a 10 mm ball at arm's length

}  // namespace

Result<LesionDrawable> LesionDrawable::create() {
  LesionDrawable d;
  auto program = build_program({"lesion.vert+lesion.frag", shaders::lesion_vert, shaders::lesion_frag, "", {}});
  if (!program) return fail(program.error());
  d.program_ = program.take();
  d.program_.find_uniforms({{&d.mvp_, "u_model_view_proj"},
                            {&d.eye_, "u_eye_model"},
                            {&d.centre_, "u_centre"},
                            {&d.radius_, "u_radius"},
                            {&d.color_, "u_color"},
                            {&d.ambient_, "u_ambient"}});
  std::vector<float> unit;
  for (int r = 0; r <= kRings; ++r) {
    const double polar = std::numbers::pi * r / kRings;
    for (int s = 0; s <= kSegments; ++s) {
      const double azimuth = 2 * std::numbers::pi * s / kSegments;
      unit.push_back(static_cast<float>(std::sin(polar) * std::cos(azimuth)));
      unit.push_back(static_cast<float>(std::sin(polar) * std::sin(azimuth)));
      unit.push_back(static_cast<float>(std::cos(polar)));
    }
  }
  std::vector<std::uint32_t> index;
  const auto at = [](int r, int s) { return static_cast<std::uint32_t>(r * (kSegments + 1) + s); };
  for (int r = 0; r < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      // Counter-clockwise seen from outside: down the meridian, then along the ring.
      index.insert(index.end(), {at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      index.insert(index.end(), {at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  d.index_count_ = static_cast<std::uint32_t>(index.size());
  d.vao_ = gl::VertexArray::create();
  d.vertices_ = gl::Buffer::create();
  d.indices_ = gl::Buffer::create();
  glBindVertexArray(d.vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, d.vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(unit.size() * sizeof(float)), unit.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(index.size() * sizeof(std::uint32_t)), index.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  return d;
}

void LesionDrawable::draw(std::span<const LesionFrame> lesions, const glm::mat4& model, std::span<const EyeView> eyes,
                          float ambient) const {
  if (lesions.empty()) return;
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glUseProgram(program_.id());
  glBindVertexArray(vao_.id());
  glUniform1f(ambient_, ambient);
  for (const EyeView& eye : eyes) {
    glViewport(eye.viewport.x, eye.viewport.y, eye.viewport.width, eye.viewport.height);
    for (const LesionFrame& l : lesions) {
      const glm::mat4 lung = model * l.rest_transform;
      const glm::mat4 mvp = eye.projection * eye.view * lung;
      const glm::vec4 eye_lung = glm::inverse(eye.view * lung) * glm::vec4(0.f, 0.f, 0.f, 1.f);
      glUniformMatrix4fv(mvp_, 1, GL_FALSE, glm::value_ptr(mvp));
      glUniform3f(eye_, eye_lung.x, eye_lung.y, eye_lung.z);
      glUniform3f(centre_, l.centre_mm.x, l.centre_mm.y, l.centre_mm.z);
      glUniform1f(radius_, l.radius_mm);
      glUniform3f(color_, l.color.r, l.color.g, l.color.b);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
    }
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace lungar::render
