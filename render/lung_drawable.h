/// @file lung_drawable.h
/// @brief GPU buffers of a baked asset: rest positions, normals, per-vertex coefficients T^I_lm, triangles, and a
/// buffer of deformed positions (written by transform feedback or uploaded from the CPU).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "config/base/result.h"
#include "render/drawable_options.h"
#include "render/gl_objects.h"
#include "sim/asset/baked_asset.h"

namespace lungar::render {

/// One lung's share of the vertex array, with what level of detail needs.
struct LungRange {
  std::uint32_t first_vertex = 0;
  std::uint32_t vertex_count = 0;
  std::uint32_t first_index = 0;
  std::uint32_t index_count = 0;
  double surface_area_mm2 = 0;  ///< sum of the vertex areas
  glm::vec3 bound_centre{0.f};  ///< bounding sphere of the rest shape, lung frame
  float bound_radius = 0;
};

/// Coefficients attributes are limited by GL_MAX_VERTEX_ATTRIBS (16 in GLES 3): 9 vec4 plus position and normal.
inline constexpr std::uint32_t kMaxAttributeCoefficients = 36;
/// Up to this many coefficients, Auto keeps them in attributes on every renderer.
inline constexpr std::uint32_t kAlwaysAttributeCoefficients = 16;

/// Whether the coefficients go to a texture. Auto follows what was measured at 400k nodes, stereo points
/// (docs/measurements.md, "Where the coefficients live"): on a hardware GPU (an H200), 16 coefficients in attributes
/// cost nothing over the undeformed frame, 36 in attributes 10 % and 36 in a texture 2 %; on a software rasteriser
/// (llvmpipe), where each vertex fetch runs on the CPU, the texture is the slower at 36 (1.34 against 1.24). So:
/// attributes up to 16 everywhere, up to 36 on a software rasteriser, else the texture. `renderer` is GL_RENDERER.
bool coefficients_in_texture(CoeffStorage storage, std::uint32_t coefficients, std::string_view renderer);

/// The attribute of each vertex's direction of motion e_I (render/shaders/deform.vert's a_direction), after the
/// nine coefficient attributes 2 .. 10.
inline constexpr unsigned kDirectionAttribute = 11;
/// The three rows of the off-axis basis (render/shaders/deform.vert's a_off_x, a_off_y, a_off_z).
inline constexpr unsigned kOffAxisAttribute = 12;

class LungDrawable {
 public:
  /// Validates the asset (array sizes, lung ranges, indices) and uploads it; needs a current GLES 3 context.
  static Result<LungDrawable> create(const sim::BakedAsset& asset, const DrawableOptions& options = {});

  std::uint32_t vertex_count() const { return vertex_count_; }
  std::uint32_t coefficients() const { return coefficients_; }  ///< per vertex: L^2, or 4 for the linear basis
  std::uint32_t coeff_vec4() const { return (coefficients_ + 3) / 4; }
  bool uses_texture() const { return uses_texture_; }
  bool half_float() const { return half_float_; }
  /// The sliding model's off-axis basis is bound (attributes kOffAxisAttribute .. + 2).
  bool has_off_axis() const { return has_off_axis_; }
  Basis basis() const { return basis_; }
  const std::vector<LungRange>& lungs() const { return lungs_; }
  bool has_triangles() const { return index_count_ > 0; }

  /// Replaces the deformed positions (3 floats per vertex, lung frame, mm): the CPU eq. (7)/(1) baselines draw these
  /// without the shader deformation. Returns an error if the size is wrong.
  Status upload_positions(std::span<const float> xyz);

  // For the renderer (same folder): vertex arrays that read rest or deformed positions.
  std::uint32_t rest_vao() const { return rest_vao_.id(); }
  std::uint32_t rest_plain_vao() const { return rest_plain_vao_.id(); }  ///< rest positions and normals only
  std::uint32_t deformed_vao() const { return deformed_vao_.id(); }
  std::uint32_t deformed_buffer() const { return deformed_.id(); }
  std::uint32_t coeff_texture() const { return coeff_texture_.id(); }
  std::int32_t coeff_texture_width() const { return coeff_texture_width_; }

 private:
  LungDrawable() = default;
  Status upload_coefficients(const std::vector<float>& padded);
  Status upload_coefficient_texture(std::vector<float> padded);
  void build_vertex_arrays();

  std::uint32_t vertex_count_ = 0;
  std::uint32_t coefficients_ = 0;
  std::uint32_t index_count_ = 0;
  bool uses_texture_ = false;
  bool half_float_ = false;
  bool has_off_axis_ = false;
  Basis basis_ = Basis::SphericalHarmonics;
  std::vector<LungRange> lungs_;
  gl::Buffer positions_, normals_, directions_, off_axis_, coeffs_, indices_, deformed_;
  gl::Texture coeff_texture_;
  std::int32_t coeff_texture_width_ = 0;
  gl::VertexArray rest_vao_, rest_plain_vao_, deformed_vao_;
};

}  // namespace lungar::render
