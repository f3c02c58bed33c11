/// @file renderer.h
/// @brief Draws the lungs of a LungDrawable for one or two eyes: points (default) or mesh, deformed by eq. (7) in
/// the vertex shader, per eye (the paper, and the default) or once by transform feedback then both eyes, or drawn from
/// CPU-deformed positions; with level of detail, back-face culling of points and an optional grey rest overlay.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "config/base/result.h"
#include "render/draw_modes.h"
#include "render/gl_objects.h"
#include "render/lung_drawable.h"
#include "render/stereo_view.h"

namespace lungar::render {

/// Per lung, per frame.
struct LungFrame {
  std::span<const float> force;   ///< f_lm, drawable.coefficients() values, mm per mL per unit of T (normalised)
  float volume_change_ml = 0.f;   ///< dV; the vertex moves by dV times its displacement per mL
  glm::vec3 color{0.9f, 0.45f, 0.45f};
  /// The linear weights w of the orientation (sim/force/force_sh.h, linear_weights), mm per mL per unit of the
  /// off-axis basis. Read only for a drawable with the off-axis part (the sliding model).
  std::array<float, 4> linear{};
  /// The lung's volume swing over the last breath, mL: the ventilation map colours each point by the depth its
  /// patch of surface swept in it (FrameInputs::ventilation_full_scale_mm).
  float sweep_ml = 0.f;
  /// The lung's rest shape now, from the one uploaded (lung frame): a pathology changing during the run
  /// (platform/runtime/lung_course.h); identity otherwise.
  glm::mat4 rest_transform{1.f};
};

struct FrameInputs {
  std::span<const LungFrame> lungs;   ///< one per drawable lung
  std::span<const EyeView> eyes;      ///< one (mono) or two (stereo)
  glm::mat4 model{1.f};               ///< lung frame -> world (the registration)
  DrawMode mode = DrawMode::Points;
  PositionSource source = PositionSource::Shader;
  /// For two eyes (one eye deforms in its draw); per-eye is measured faster (docs/measurements.md).
  StereoStrategy strategy = StereoStrategy::PerEye;
  bool overlay_rest = false;          ///< the rest shape in grey under the deformed lungs (the paper's Fig. 10)
  float point_size_px = 5.f;          ///< the paper: 5
  bool level_of_detail = true;        ///< draw count from the projected size (points mode)
  float lod_coverage = 3.f;           ///< see lod_point_count(): hole-free for sim's bake order at 3
  bool cull_back_facing = true;       ///< points mode
  float ambient = 0.3f;
  glm::vec3 rest_color{0.55f, 0.55f, 0.55f};
  /// > 0: the ventilation map: each deformed point coloured by the depth of air (mm, volume per area) its patch
  /// of surface swept over the last breath (LungFrame::sweep_ml), this depth at the ramp's top
  /// (render/ventilation_ramp.h); 0: the lungs' colours. Drawn per eye whatever the strategy.
  float ventilation_full_scale_mm = 0.f;
  bool clear = true;                  ///< clear the bound framebuffer to `background` first
  glm::vec3 background{0.f};
};

/// What a frame drew, per eye.
struct FrameStats {
  std::uint32_t points_deformed = 0;                 ///< by the transform-feedback pass
  std::array<std::uint32_t, 2> points_drawn{0, 0};   ///< per eye (before culling)
};

inline constexpr std::size_t kMaxLungs = 8;

class Renderer {
 public:
  /// Builds the programs for the drawable's coefficient layout (count, attributes or texture).
  static Result<Renderer> create(const LungDrawable& drawable);

  /// Draws into the bound framebuffer. Allocates nothing; returns an error for inputs that do not fit the drawable.
  Status draw(const LungDrawable& drawable, const FrameInputs& frame, FrameStats* stats = nullptr);

  /// Evaluates eq. (7) for every vertex by transform feedback and reads the deformed positions back
  /// (3 floats per vertex): the shader's own output, for tests against the CPU reference.
  Status capture_deformed(const LungDrawable& drawable, std::span<const LungFrame> lungs, std::vector<float>& xyz);

 private:
  struct Slots {
    gl::Program program;
    std::int32_t force = -1, linear = -1, volume = -1, sweep_ml = -1, coeff = -1, coeff_width = -1, mvp = -1, eye = -1,
                 color = -1, ambient = -1, point_size = -1, sweep_scale = -1;
  };
  enum Variant { kDeformCull, kDeformNoCull, kPlainCull, kPlainNoCull, kCapture, kVariants };

  Renderer() = default;
  Status check(const LungDrawable& drawable, std::span<const LungFrame> lungs, bool needs_force) const;
  void use(const LungDrawable& drawable, Variant v) const;
  void set_force(Variant v, const LungFrame& lung);
  void set_eye(Variant v, const glm::mat4& model, const EyeView& eye, const glm::vec3& color, const FrameInputs& f) const;
  void deform_once(const LungDrawable& drawable, std::span<const LungFrame> lungs,
                   std::span<const std::uint32_t> counts);
  void draw_lungs(const LungDrawable& drawable, Variant v, std::uint32_t vao, const FrameInputs& f, const EyeView& eye,
                  std::span<const std::uint32_t> counts, bool rest_overlay);

  std::uint32_t coeff_vec4_ = 0;
  std::uint32_t coefficients_ = 0;
  std::array<Slots, kVariants> slots_;
  std::vector<float> padded_force_;  ///< f, zero-padded to whole vec4s (dV goes apart); sized once
  gl::TransformFeedback feedback_;
  gl::Framebuffer capture_fbo_;      ///< transform feedback needs a complete framebuffer even with no raster
  gl::Renderbuffer capture_rb_;
};

}  // namespace lungar::render
