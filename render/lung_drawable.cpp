/// @file lung_drawable.cpp
/// @brief Validation and upload of a baked asset into GL buffers.
#include "render/lung_drawable.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>

namespace lungar::render {
namespace {

std::string size_error(const char* field, std::size_t expected, std::size_t got) {
  return "baked asset: field '" + std::string(field) + "': expected " + std::to_string(expected) + " values, got " +
         std::to_string(got);
}

// Checks every array against the vertex count; empty string when the asset is drawable.
std::string validate(const sim::BakedAsset& a, const DrawableOptions& o) {
  const std::size_t n = a.vertex_count();
  if (n == 0) return "baked asset: field 'lung_of_vertex': expected at least one vertex, got 0";
  if (a.positions.size() != 3 * n) return size_error("positions", 3 * n, a.positions.size());
  if (a.normals.size() != 3 * n) return size_error("normals", 3 * n, a.normals.size());
  if (a.directions.size() != 3 * n) return size_error("directions", 3 * n, a.directions.size());
  if (a.has_off_axis() && a.off_axis.size() != 12 * n) return size_error("off_axis", 12 * n, a.off_axis.size());
  if (!a.areas.empty() && a.areas.size() != n) return size_error("areas", n, a.areas.size());
  if (o.basis == Basis::SphericalHarmonics) {
    if (a.bands == 0 || a.bands > 10) {
      return "baked asset: field 'bands': expected 1..10, got " + std::to_string(a.bands);
    }
    if (a.sh_coeffs.size() != a.coefficients() * n) return size_error("sh_coeffs", a.coefficients() * n, a.sh_coeffs.size());
  } else if (a.linear_coeffs.size() != 4 * n) {
    return size_error("linear_coeffs", 4 * n, a.linear_coeffs.size());
  }
  if (a.triangles.size() % 3 != 0) return "baked asset: field 'triangles': expected a multiple of 3 indices";
  for (std::uint32_t index : a.triangles) {
    if (index >= n) return "baked asset: field 'triangles': expected indices below " + std::to_string(n) + ", got " +
                           std::to_string(index);
  }
  if (a.lungs.empty()) return "baked asset: field 'lungs': expected at least one lung, got none";
  for (std::size_t i = 0; i < a.lungs.size(); ++i) {
    const auto& l = a.lungs[i];
    const std::string field = "lungs[" + std::to_string(i) + "]";
    if (std::uint64_t{l.first_vertex} + l.vertex_count > n || l.vertex_count == 0) {
      return "baked asset: field '" + field + ".vertex range': expected a non-empty range within " +
             std::to_string(n) + " vertices";
    }
    if (std::uint64_t{l.first_index} + l.index_count > a.triangles.size()) {
      return "baked asset: field '" + field + ".index range': expected a range within " +
             std::to_string(a.triangles.size()) + " indices";
    }
  }
  for (std::uint8_t lung : a.lung_of_vertex) {
    if (lung >= a.lungs.size()) return "baked asset: field 'lung_of_vertex': expected values below the lung count";
  }
  return {};
}

// Bounding sphere about the box centre (good enough for level of detail, which only needs the scale).
void bound(const sim::BakedAsset& a, LungRange& r) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (std::uint32_t v = r.first_vertex; v < r.first_vertex + r.vertex_count; ++v) {
    const glm::vec3 p(a.positions[3 * v], a.positions[3 * v + 1], a.positions[3 * v + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  r.bound_centre = 0.5f * (lo + hi);
  r.bound_radius = 0.5f * glm::length(hi - lo);
  double area = 0;
  for (std::uint32_t v = r.first_vertex; v < r.first_vertex + r.vertex_count && !a.areas.empty(); ++v) area += a.areas[v];
  // Without areas (never from the bake), estimate the surface from the bounding sphere.
  r.surface_area_mm2 = area > 0 ? area : 4.0 * M_PI * r.bound_radius * r.bound_radius;
}

void upload(gl::Buffer& buffer, GLenum target, const void* data, std::size_t bytes, GLenum usage) {
  buffer = gl::Buffer::create();
  glBindBuffer(target, buffer.id());
  glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
}

/// Coefficients padded to whole vec4s, vertex-major: vertex v's k-th vec4 is element v * coeff_vec4 + k.
std::vector<float> padded_coefficients(const std::vector<float>& src, std::uint32_t n, std::uint32_t coefficients,
                                       std::uint32_t nv4) {
  std::vector<float> padded(std::size_t{n} * nv4 * 4, 0.f);
  for (std::uint32_t v = 0; v < n; ++v) {
    std::copy_n(src.begin() + std::size_t{v} * coefficients, coefficients, padded.begin() + std::size_t{v} * nv4 * 4);
  }
  return padded;
}

std::vector<std::uint16_t> to_half(const std::vector<float>& values) {
  std::vector<std::uint16_t> halves(values.size());
  std::transform(values.begin(), values.end(), halves.begin(), [](float x) { return glm::packHalf1x16(x); });
  return halves;
}

/// Positions (attribute 0) and normals (attribute 1), 3 floats each.
void position_and_normal_attributes(const gl::Buffer& positions, const gl::Buffer& normals) {
  glBindBuffer(GL_ARRAY_BUFFER, positions.id());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, normals.id());
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 12, nullptr);
}

}  // namespace

bool coefficients_in_texture(CoeffStorage storage, std::uint32_t coefficients, std::string_view renderer) {
  if (storage != CoeffStorage::Auto) return storage == CoeffStorage::Texture;
  if (coefficients <= kAlwaysAttributeCoefficients) return false;
  if (coefficients > kMaxAttributeCoefficients) return true;
  for (std::string_view software : {"llvmpipe", "softpipe", "swrast", "SwiftShader"}) {
    if (renderer.find(software) != std::string_view::npos) return false;
  }
  return true;
}

Result<LungDrawable> LungDrawable::create(const sim::BakedAsset& asset, const DrawableOptions& options) {
  if (std::string error = validate(asset, options); !error.empty()) return fail(error);
  LungDrawable d;
  const std::uint32_t n = asset.vertex_count();
  d.vertex_count_ = n;
  d.basis_ = options.basis;
  d.half_float_ = options.half_float;
  d.coefficients_ = options.basis == Basis::Linear ? 4u : asset.coefficients();
  d.index_count_ = static_cast<std::uint32_t>(asset.triangles.size());
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  d.uses_texture_ = coefficients_in_texture(options.storage, d.coefficients_, renderer ? renderer : "");
  if (options.storage == CoeffStorage::Attributes && d.coefficients_ > kMaxAttributeCoefficients) {
    return fail("drawable options: field 'storage': attributes hold at most " +
                std::to_string(kMaxAttributeCoefficients) + " coefficients, the asset has " +
                std::to_string(d.coefficients_));
  }
  for (const auto& l : asset.lungs) {
    LungRange r{l.first_vertex, l.vertex_count, l.first_index, l.index_count, 0, {}, 0};
    bound(asset, r);
    d.lungs_.push_back(r);
  }
  upload(d.positions_, GL_ARRAY_BUFFER, asset.positions.data(), asset.positions.size() * 4, GL_STATIC_DRAW);
  upload(d.normals_, GL_ARRAY_BUFFER, asset.normals.data(), asset.normals.size() * 4, GL_STATIC_DRAW);
  upload(d.directions_, GL_ARRAY_BUFFER, asset.directions.data(), asset.directions.size() * 4, GL_STATIC_DRAW);
  d.has_off_axis_ = asset.has_off_axis();
  if (d.has_off_axis_) upload(d.off_axis_, GL_ARRAY_BUFFER, asset.off_axis.data(), asset.off_axis.size() * 4, GL_STATIC_DRAW);
  // The deformed copy starts as the rest shape: drawing it before any deformation shows the rest lungs.
  upload(d.deformed_, GL_ARRAY_BUFFER, asset.positions.data(), asset.positions.size() * 4, GL_DYNAMIC_COPY);
  if (d.index_count_ > 0) {
    upload(d.indices_, GL_ELEMENT_ARRAY_BUFFER, asset.triangles.data(), asset.triangles.size() * 4, GL_STATIC_DRAW);
  }
  const std::vector<float>& src = options.basis == Basis::Linear ? asset.linear_coeffs : asset.sh_coeffs;
  std::vector<float> padded = padded_coefficients(src, n, d.coefficients_, d.coeff_vec4());
  if (Status coeffs = d.uses_texture_ ? d.upload_coefficient_texture(std::move(padded)) : d.upload_coefficients(padded);
      !coeffs) {
    return coeffs.with_context("");
  }
  d.build_vertex_arrays();
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    char text[64];
    std::snprintf(text, sizeof text, "baked asset upload: GL error 0x%04x", err);
    return fail(text);
  }
  return d;
}

Status LungDrawable::upload_coefficients(const std::vector<float>& padded) {
  if (half_float_) {
    const std::vector<std::uint16_t> halves = to_half(padded);
    upload(coeffs_, GL_ARRAY_BUFFER, halves.data(), halves.size() * 2, GL_STATIC_DRAW);
  } else {
    upload(coeffs_, GL_ARRAY_BUFFER, padded.data(), padded.size() * 4, GL_STATIC_DRAW);
  }
  return ok();
}

/// Coefficients beyond the attribute limit go to a float texture read by gl_VertexID, 4096 texels a row.
Status LungDrawable::upload_coefficient_texture(std::vector<float> padded) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  const std::size_t texels = std::size_t{vertex_count_} * coeff_vec4();
  const GLint width = std::min<GLint>(max_size, 4096);
  const std::size_t height = (texels + width - 1) / static_cast<std::size_t>(width);
  if (height > static_cast<std::size_t>(max_size)) {
    return fail("baked asset: field 'sh_coeffs': " + std::to_string(texels) + " texels exceed the GL texture limit of " +
                std::to_string(max_size) + "^2");
  }
  padded.resize(height * static_cast<std::size_t>(width) * 4, 0.f);  // the last row is partial: whole rows
  coeff_texture_ = gl::Texture::create();
  coeff_texture_width_ = width;
  glBindTexture(GL_TEXTURE_2D, coeff_texture_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // float textures are not filterable
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  const auto h = static_cast<GLsizei>(height);
  if (half_float_) {
    const std::vector<std::uint16_t> halves = to_half(padded);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, width, h, 0, GL_RGBA, GL_HALF_FLOAT, halves.data());
  } else {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, h, 0, GL_RGBA, GL_FLOAT, padded.data());
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  return ok();
}

/// rest_vao: rest positions, normals, directions of motion, the off-axis basis (sliding model) and (attribute
/// storage) coefficients, for the deforming programs.
/// deformed_vao: deformed positions and the normals, for drawing without the shader deformation; rest_plain_vao:
/// the same for the rest shape (no coefficient arrays enabled, so none are fetched).
void LungDrawable::build_vertex_arrays() {
  rest_vao_ = gl::VertexArray::create();
  glBindVertexArray(rest_vao_.id());
  position_and_normal_attributes(positions_, normals_);
  glBindBuffer(GL_ARRAY_BUFFER, directions_.id());
  glEnableVertexAttribArray(kDirectionAttribute);
  glVertexAttribPointer(kDirectionAttribute, 3, GL_FLOAT, GL_FALSE, 12, nullptr);
  if (has_off_axis_) {
    glBindBuffer(GL_ARRAY_BUFFER, off_axis_.id());
    for (unsigned row = 0; row < 3; ++row) {
      glEnableVertexAttribArray(kOffAxisAttribute + row);
      glVertexAttribPointer(kOffAxisAttribute + row, 4, GL_FLOAT, GL_FALSE, 48,
                            reinterpret_cast<const void*>(std::uintptr_t{16} * row));
    }
  }
  if (!uses_texture_) {
    glBindBuffer(GL_ARRAY_BUFFER, coeffs_.id());
    const GLsizei value_bytes = half_float_ ? 2 : 4;
    const GLsizei stride = static_cast<GLsizei>(coeff_vec4() * 4) * value_bytes;
    for (std::uint32_t k = 0; k < coeff_vec4(); ++k) {
      glEnableVertexAttribArray(2 + k);
      const auto offset = static_cast<std::uintptr_t>(k * 4 * value_bytes);
      glVertexAttribPointer(2 + k, 4, half_float_ ? GL_HALF_FLOAT : GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<const void*>(offset));
    }
  }
  if (index_count_ > 0) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  for (auto [vao, positions] : {std::pair{&deformed_vao_, &deformed_}, std::pair{&rest_plain_vao_, &positions_}}) {
    *vao = gl::VertexArray::create();
    glBindVertexArray(vao->id());
    position_and_normal_attributes(*positions, normals_);
    if (index_count_ > 0) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

Status LungDrawable::upload_positions(std::span<const float> xyz) {
  if (xyz.size() != std::size_t{vertex_count_} * 3) {
    return fail("upload_positions: expected " + std::to_string(std::size_t{vertex_count_} * 3) + " floats, got " +
                std::to_string(xyz.size()));
  }
  glBindBuffer(GL_ARRAY_BUFFER, deformed_.id());
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(xyz.size_bytes()), xyz.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return ok();
}

}  // namespace lungar::render
