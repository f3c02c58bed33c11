/// @file synthetic_lungs.cpp
/// @brief Ellipsoid-pair assets for tests and benchmarks.
#include "tests/render/synthetic_lungs.h"

#include <cmath>
#include <random>

namespace lungar::test {
namespace {

constexpr double kAxes[3] = {60.0, 80.0, 120.0};
constexpr double kCentreX[2] = {-90.0, 90.0};  // right lung (patient's right is -x in LPS), then left

// The ellipsoid point, outward normal and area scale for unit-sphere direction s.
void on_ellipsoid(int lung, const double s[3], float* p, float* n, double* area_scale) {
  double g[3], len = 0;
  for (int k = 0; k < 3; ++k) {
    g[k] = s[k] / kAxes[k];
    len += g[k] * g[k];
  }
  len = std::sqrt(len);
  for (int k = 0; k < 3; ++k) {
    p[k] = static_cast<float>(kAxes[k] * s[k] + (k == 0 ? kCentreX[lung] : 0.0));
    n[k] = static_cast<float>(g[k] / len);
  }
  // The map s -> diag(axes) s scales area by det * |diag(axes)^-T s|.
  *area_scale = kAxes[0] * kAxes[1] * kAxes[2] * len;
}

void add_lung(sim::BakedAsset& a, int lung, std::uint32_t first, std::uint32_t count) {
  sim::BakedLung l;
  l.name = lung == 0 ? "right" : "left";
  l.centre = {static_cast<float>(kCentreX[lung]), 0.f, 0.f};
  l.first_vertex = first;
  l.vertex_count = count;
  l.rest_volume_ml = 4.0 / 3.0 * M_PI * kAxes[0] * kAxes[1] * kAxes[2] / 1000.0;
  a.lungs.push_back(l);
}

/// Directions of motion tilted away from the normals towards the feet, as the sliding model's are, so that a
/// shader or CPU path that moved the vertices along their normals instead would be caught.
void tilted_directions(sim::BakedAsset& a) {
  a.directions.resize(a.normals.size());
  for (std::size_t i = 0; i < a.normals.size(); i += 3) {
    double d[3] = {a.normals[i], a.normals[i + 1], a.normals[i + 2] - 1.2};
    double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (norm < 1e-6) {
      d[0] = 1;
      norm = 1;
    }
    for (int k = 0; k < 3; ++k) a.directions[i + k] = static_cast<float>(d[k] / norm);
  }
}

void random_coefficients(sim::BakedAsset& a, std::uint32_t bands, std::uint32_t seed, float scale) {
  tilted_directions(a);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-scale, scale);
  a.bands = bands;
  a.sh_coeffs.resize(std::size_t{a.vertex_count()} * bands * bands);
  for (float& c : a.sh_coeffs) c = u(rng);
  a.linear_coeffs.resize(std::size_t{a.vertex_count()} * 4);
  for (float& c : a.linear_coeffs) c = u(rng);
}

}  // namespace

sim::BakedAsset ellipsoid_pair(std::uint32_t points_per_lung, std::uint32_t bands, std::uint32_t seed, float scale) {
  sim::BakedAsset a;
  const std::size_t n = std::size_t{points_per_lung} * 2;
  a.positions.resize(3 * n);
  a.normals.resize(3 * n);
  a.areas.resize(n);
  a.lung_of_vertex.resize(n);
  // R2 sequence (Roberts): each prefix is evenly spread over the unit square, hence (equal-area map) the sphere.
  const double g = 1.32471795724474602596;  // plastic number
  const double a1 = 1.0 / g, a2 = 1.0 / (g * g);
  for (int lung = 0; lung < 2; ++lung) {
    for (std::uint32_t i = 0; i < points_per_lung; ++i) {
      const double u = std::fmod(0.5 + a1 * i, 1.0), v = std::fmod(0.5 + a2 * i, 1.0);
      const double z = 1.0 - 2.0 * u, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * M_PI * v;
      const double s[3] = {r * std::cos(phi), r * std::sin(phi), z};
      const std::size_t idx = std::size_t{points_per_lung} * lung + i;
      double scale_area = 0;
      on_ellipsoid(lung, s, &a.positions[3 * idx], &a.normals[3 * idx], &scale_area);
      a.areas[idx] = static_cast<float>(4.0 * M_PI / points_per_lung * scale_area);
      a.lung_of_vertex[idx] = static_cast<std::uint8_t>(lung);
    }
    add_lung(a, lung, points_per_lung * lung, points_per_lung);
  }
  random_coefficients(a, bands, seed, scale);
  return a;
}

sim::BakedAsset ellipsoid_pair_mesh(std::uint32_t rings, std::uint32_t segments, std::uint32_t bands,
                                    std::uint32_t seed) {
  sim::BakedAsset a;
  const std::uint32_t per_lung = (rings + 1) * segments;
  for (int lung = 0; lung < 2; ++lung) {
    const std::uint32_t first = per_lung * lung;
    for (std::uint32_t r = 0; r <= rings; ++r) {
      const double theta = M_PI * r / rings;
      for (std::uint32_t k = 0; k < segments; ++k) {
        const double phi = 2.0 * M_PI * k / segments;
        const double s[3] = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
        float p[3], n[3];
        double unused = 0;
        on_ellipsoid(lung, s, p, n, &unused);
        a.positions.insert(a.positions.end(), p, p + 3);
        a.normals.insert(a.normals.end(), n, n + 3);
        a.lung_of_vertex.push_back(static_cast<std::uint8_t>(lung));
      }
    }
    const auto first_index = static_cast<std::uint32_t>(a.triangles.size());
    for (std::uint32_t r = 0; r < rings; ++r) {
      for (std::uint32_t k = 0; k < segments; ++k) {
        const std::uint32_t i0 = first + r * segments + k, i1 = first + r * segments + (k + 1) % segments;
        const std::uint32_t j0 = i0 + segments, j1 = i1 + segments;
        a.triangles.insert(a.triangles.end(), {i0, j0, i1, i1, j0, j1});
      }
    }
    add_lung(a, lung, first, per_lung);
    a.lungs.back().first_index = first_index;
    a.lungs.back().index_count = static_cast<std::uint32_t>(a.triangles.size()) - first_index;
  }
  // Vertex areas: a third of each triangle's area.
  a.areas.assign(a.vertex_count(), 0.f);
  for (std::size_t t = 0; t < a.triangles.size(); t += 3) {
    const float* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &a.positions[3 * a.triangles[t + k]];
    double e1[3], e2[3];
    for (int k = 0; k < 3; ++k) {
      e1[k] = p[1][k] - p[0][k];
      e2[k] = p[2][k] - p[0][k];
    }
    const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
    const double third = std::sqrt(cx * cx + cy * cy + cz * cz) / 6.0;
    for (int k = 0; k < 3; ++k) a.areas[a.triangles[t + k]] += static_cast<float>(third);
  }
  random_coefficients(a, bands, seed, 0.05f);
  return a;
}

void set_local_transfer(sim::BakedAsset& a, float w) {
  a.bands = 2;
  a.sh_coeffs.assign(std::size_t{a.vertex_count()} * 4, 0.f);
  for (std::uint32_t v = 0; v < a.vertex_count(); ++v) {
    const auto& c = a.lungs[a.lung_of_vertex[v]].centre;
    double d[3], len = 0;
    for (int k = 0; k < 3; ++k) {
      d[k] = a.positions[3 * v + k] - c[k];
      len += d[k] * d[k];
    }
    len = std::sqrt(len);
    // Real orthonormal SH, l <= 1, index l^2 + l + m: Y00, Y1-1 ~ y, Y10 ~ z, Y11 ~ x.
    const double y[4] = {0.28209479177387814, 0.4886025119029199 * d[1] / len, 0.4886025119029199 * d[2] / len,
                         0.4886025119029199 * d[0] / len};
    for (int k = 0; k < 4; ++k) a.sh_coeffs[4 * v + k] = static_cast<float>(w * a.areas[v] * y[k]);
  }
}

std::vector<double> deform_eq7(const sim::BakedAsset& a, const std::vector<std::vector<float>>& force,
                               const std::vector<float>& volume_change_ml, bool linear_basis) {
  const std::uint32_t nc = linear_basis ? 4 : a.coefficients();
  const std::vector<float>& t = linear_basis ? a.linear_coeffs : a.sh_coeffs;
  std::vector<double> out(a.positions.size());
  for (std::uint32_t v = 0; v < a.vertex_count(); ++v) {
    const int lung = a.lung_of_vertex[v];
    double d = 0;  // eq. (7): D_I = dV sum_lm T^I_lm f_lm
    for (std::uint32_t k = 0; k < nc; ++k) d += double{t[std::size_t{v} * nc + k]} * force[lung][k];
    d *= volume_change_ml[lung];
    for (int k = 0; k < 3; ++k) out[3 * v + k] = a.positions[3 * v + k] + d * a.directions[3 * v + k];
  }
  return out;
}

}  // namespace lungar::test
