/// @file renderer.cpp
/// @brief Frame drawing: program variants, the transform-feedback deformation pass, per-eye point and mesh draws.
#include "render/renderer.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "lungar/render/shaders.h"
#include "render/level_of_detail.h"
#include "render/shader_program.h"

namespace lungar::render {

Result<Renderer> Renderer::create(const LungDrawable& drawable) {
  Renderer r;
  r.coeff_vec4_ = drawable.coeff_vec4();
  r.coefficients_ = drawable.coefficients();
  r.padded_force_.assign(std::size_t{r.coeff_vec4_} * 4, 0.f);
  const std::string layout = "#define COEFF_VEC4 " + std::to_string(r.coeff_vec4_) + "\n#define COEFF_TEXTURE " +
                             (drawable.uses_texture() ? "1" : "0") + "\n#define OFF_AXIS " +
                             (drawable.has_off_axis() ? "1" : "0") + "\n";
  struct VariantSpec {
    bool deform, cull, capture;
    const char* name;
  };
  const VariantSpec specs[kVariants] = {{true, true, false, "deform+cull"},
                                        {true, false, false, "deform"},
                                        {false, true, false, "plain+cull"},
                                        {false, false, false, "plain"},
                                        {true, false, true, "capture"}};
  for (int v = 0; v < kVariants; ++v) {
    ProgramSource src;
    src.name = std::string("deform.vert+points.frag [") + specs[v].name + "]";
    src.vertex = shaders::deform_vert;
    src.fragment = shaders::points_frag;
    src.defines = layout + "#define DEFORM " + (specs[v].deform ? "1" : "0") + "\n#define CULL " +
                  (specs[v].cull ? "1" : "0") + "\n";
    if (specs[v].capture) src.captured = {"v_position"};
    auto program = build_program(src);
    if (!program) return fail(program.error());
    Slots& s = r.slots_[v];
    s.program = program.take();
    s.program.find_uniforms({{&s.force, "u_force"}, {&s.linear, "u_linear"}, {&s.volume, "u_volume"},
                             {&s.sweep_ml, "u_sweep_ml"}, {&s.coeff, "u_coeff"}, {&s.coeff_width, "u_coeff_width"},
                             {&s.mvp, "u_model_view_proj"}, {&s.eye, "u_eye_model"}, {&s.color, "u_color"},
                             {&s.ambient, "u_ambient"}, {&s.point_size, "u_point_size"},
                             {&s.sweep_scale, "u_sweep_full_scale_mm"}});
    glUseProgram(s.program.id());
    if (s.coeff >= 0) glUniform1i(s.coeff, 0);  // texture unit 0
  }
  glUseProgram(0);
  r.feedback_ = gl::TransformFeedback::create();
  r.capture_rb_ = gl::Renderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, r.capture_rb_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  r.capture_fbo_ = gl::Framebuffer::create();
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_FRAMEBUFFER, r.capture_fbo_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, r.capture_rb_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  return r;
}

Status Renderer::check(const LungDrawable& drawable, std::span<const LungFrame> lungs, bool needs_force) const {
  if (drawable.coeff_vec4() != coeff_vec4_ || drawable.coefficients() != coefficients_) {
    return fail("renderer: drawable: expected the coefficient layout the renderer was created for");
  }
  if (lungs.size() != drawable.lungs().size() || lungs.size() > kMaxLungs) {
    return fail("renderer: frame lungs: expected " + std::to_string(drawable.lungs().size()) + " (at most " +
            std::to_string(kMaxLungs) + "), got " + std::to_string(lungs.size()));
  }
  for (std::size_t i = 0; needs_force && i < lungs.size(); ++i) {
    if (lungs[i].force.size() != coefficients_) {
      return fail("renderer: frame lungs[" + std::to_string(i) + "].force: expected " + std::to_string(coefficients_) +
              " coefficients, got " + std::to_string(lungs[i].force.size()));
    }
  }
  return ok();
}

void Renderer::use(const LungDrawable& drawable, Variant v) const {
  glUseProgram(slots_[v].program.id());
  if (slots_[v].coeff >= 0) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, drawable.coeff_texture());
    glUniform1i(slots_[v].coeff_width, drawable.coeff_texture_width());
  }
}

void Renderer::set_force(Variant v, const LungFrame& lung) {
  // The shader sees f per mL and dV apart: it moves the vertex by dV times the per-mL displacement, and the
  // ventilation map needs that displacement per mL (times the last tidal volume).
  std::copy_n(lung.force.begin(), coefficients_, padded_force_.begin());
  glUniform4fv(slots_[v].force, static_cast<GLsizei>(coeff_vec4_), padded_force_.data());
  if (slots_[v].linear >= 0) glUniform4f(slots_[v].linear, lung.linear[0], lung.linear[1], lung.linear[2], lung.linear[3]);
  glUniform1f(slots_[v].volume, lung.volume_change_ml);
  if (slots_[v].sweep_ml >= 0) glUniform1f(slots_[v].sweep_ml, lung.sweep_ml);
}

void Renderer::set_eye(Variant v, const glm::mat4& model, const EyeView& eye, const glm::vec3& color,
                       const FrameInputs& f) const {
  const Slots& s = slots_[v];
  const glm::mat4 mvp = eye.projection * eye.view * model;
  const glm::vec4 eye_model = glm::inverse(eye.view * model) * glm::vec4(0.f, 0.f, 0.f, 1.f);
  glUniformMatrix4fv(s.mvp, 1, GL_FALSE, glm::value_ptr(mvp));
  glUniform3f(s.eye, eye_model.x, eye_model.y, eye_model.z);
  glUniform3f(s.color, color.r, color.g, color.b);
  glUniform1f(s.ambient, f.ambient);
  glUniform1f(s.point_size, f.point_size_px);
  // Only a draw that deforms knows each point's sweep; the rest overlay and drawn positions keep their colours.
  const bool deforms = v == kDeformCull || v == kDeformNoCull;
  if (s.sweep_scale >= 0) glUniform1f(s.sweep_scale, deforms ? f.ventilation_full_scale_mm : 0.f);
}

void Renderer::deform_once(const LungDrawable& drawable, std::span<const LungFrame> lungs,
                           std::span<const std::uint32_t> counts) {
  use(drawable, kCapture);
  glBindVertexArray(drawable.rest_vao());
  glEnable(GL_RASTERIZER_DISCARD);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback_.id());
  for (std::size_t i = 0; i < lungs.size(); ++i) {
    const LungRange& r = drawable.lungs()[i];
    if (counts[i] == 0) continue;
    set_force(kCapture, lungs[i]);
    // Capture into the lung's own slice of the deformed buffer, so vertex v stays at index v.
    glBindBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, drawable.deformed_buffer(),
                      static_cast<GLintptr>(r.first_vertex) * 12, static_cast<GLsizeiptr>(counts[i]) * 12);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, static_cast<GLint>(r.first_vertex), static_cast<GLsizei>(counts[i]));
    glEndTransformFeedback();
  }
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
  glDisable(GL_RASTERIZER_DISCARD);
}

void Renderer::draw_lungs(const LungDrawable& drawable, Variant v, std::uint32_t vao, const FrameInputs& f,
                          const EyeView& eye, std::span<const std::uint32_t> counts, bool rest_overlay) {
  glViewport(eye.viewport.x, eye.viewport.y, eye.viewport.width, eye.viewport.height);
  use(drawable, v);
  glBindVertexArray(vao);
  for (std::size_t i = 0; i < f.lungs.size(); ++i) {
    const LungRange& r = drawable.lungs()[i];
    if (v == kDeformCull || v == kDeformNoCull) set_force(v, f.lungs[i]);
    set_eye(v, f.model * f.lungs[i].rest_transform, eye, rest_overlay ? f.rest_color : f.lungs[i].color, f);
    if (f.mode == DrawMode::Mesh) {
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(r.index_count), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(static_cast<std::uintptr_t>(r.first_index) * 4));
    } else {
      glDrawArrays(GL_POINTS, static_cast<GLint>(r.first_vertex), static_cast<GLsizei>(counts[i]));
    }
  }
}

Status Renderer::draw(const LungDrawable& drawable, const FrameInputs& f, FrameStats* stats) {
  if (Status s = check(drawable, f.lungs, f.source == PositionSource::Shader); !s) return s;
  if (f.eyes.empty() || f.eyes.size() > 2) {
    return fail("renderer: frame eyes: expected 1 or 2, got " + std::to_string(f.eyes.size()));
  }
  if (f.mode == DrawMode::Mesh && !drawable.has_triangles()) {
    return fail("renderer: mode 'mesh': the asset has no triangles");
  }
  if (f.clear) {
    glDisable(GL_SCISSOR_TEST);
    glClearColor(f.background.r, f.background.g, f.background.b, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  // Draw counts per eye and lung: the level of detail for points, everything for a mesh.
  std::array<std::array<std::uint32_t, kMaxLungs>, 2> counts{};
  std::array<std::uint32_t, kMaxLungs> deform_counts{};
  for (std::size_t e = 0; e < f.eyes.size(); ++e) {
    const EyeView& eye = f.eyes[e];
    for (std::size_t i = 0; i < f.lungs.size(); ++i) {
      const LungRange& r = drawable.lungs()[i];
      std::uint32_t n = r.vertex_count;
      if (f.mode == DrawMode::Points && f.level_of_detail) {
        n = lod_point_count(r, eye.view * f.model, eye.projection[1][1], eye.viewport.height, f.point_size_px,
                            f.lod_coverage);
      }
      counts[e][i] = n;
      deform_counts[i] = std::max(deform_counts[i], n);
    }
  }
  const std::span<const std::uint32_t> lung_counts(deform_counts.data(), f.lungs.size());

  const bool points = f.mode == DrawMode::Points;
  const bool cull = points && f.cull_back_facing;
  if (f.overlay_rest) {
    for (std::size_t e = 0; e < f.eyes.size(); ++e) {
      draw_lungs(drawable, cull ? kPlainCull : kPlainNoCull, drawable.rest_plain_vao(), f, f.eyes[e],
                 std::span<const std::uint32_t>(counts[e].data(), f.lungs.size()), true);
    }
  }
  if (stats != nullptr) stats->points_deformed = 0;
  Variant variant = cull ? kPlainCull : kPlainNoCull;
  GLuint vao = drawable.deformed_vao();
  if (f.source == PositionSource::Rest) vao = drawable.rest_plain_vao();
  if (f.source == PositionSource::Shader) {
    // Deform-once pays a transform-feedback pass to share the deformation between eyes; one eye has nothing to
    // share, so it deforms in its draw.
    // The ventilation map colours by the displacement, which only a deforming draw computes: it draws per eye.
    if (f.strategy == StereoStrategy::DeformOnce && f.eyes.size() > 1 && !(f.ventilation_full_scale_mm > 0)) {
      deform_once(drawable, f.lungs, lung_counts);
      if (stats != nullptr) {
        for (std::uint32_t n : lung_counts) stats->points_deformed += n;
      }
    } else {
      variant = cull ? kDeformCull : kDeformNoCull;
      vao = drawable.rest_vao();
    }
  }
  for (std::size_t e = 0; e < f.eyes.size(); ++e) {
    draw_lungs(drawable, variant, vao, f, f.eyes[e], std::span<const std::uint32_t>(counts[e].data(), f.lungs.size()),
               false);
    if (stats != nullptr) {
      stats->points_drawn[e] = 0;
      for (std::size_t i = 0; i < f.lungs.size(); ++i) stats->points_drawn[e] += points ? counts[e][i] : 0;
    }
  }
  glBindVertexArray(0);
  return ok();
}

Status Renderer::capture_deformed(const LungDrawable& drawable, std::span<const LungFrame> lungs,
                                  std::vector<float>& xyz) {
  if (Status s = check(drawable, lungs, true); !s) return s;
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glBindFramebuffer(GL_FRAMEBUFFER, capture_fbo_.id());
  std::array<std::uint32_t, kMaxLungs> all{};
  for (std::size_t i = 0; i < lungs.size(); ++i) all[i] = drawable.lungs()[i].vertex_count;
  deform_once(drawable, lungs, std::span<const std::uint32_t>(all.data(), lungs.size()));
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));

  const std::size_t bytes = std::size_t{drawable.vertex_count()} * 12;
  xyz.resize(std::size_t{drawable.vertex_count()} * 3);
  glBindBuffer(GL_COPY_READ_BUFFER, drawable.deformed_buffer());
  const void* mapped = glMapBufferRange(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(bytes), GL_MAP_READ_BIT);
  if (mapped == nullptr) {
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    return fail("renderer: capture: could not map the deformed buffer (GL error " + std::to_string(glGetError()) + ")");
  }
  std::copy_n(static_cast<const float*>(mapped), xyz.size(), xyz.begin());
  glUnmapBuffer(GL_COPY_READ_BUFFER);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    return fail("renderer: capture: GL error " + std::to_string(err));
  }
  return ok();
}

}  // namespace lungar::render
