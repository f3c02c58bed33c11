/// @file lung_changes.cpp
/// @brief The shared lung operations and spec fields of lung_changes.h.
#include "sim/pathology/lung_changes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "sim/motion/surface_regions.h"

namespace lungar::sim::pathology {
Error bad(std::string_view spec, const std::string& why) {
  return fail("pathology '" + std::string(spec) + "': " + why);
}

std::vector<std::string_view> split_spec(std::string_view spec) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t end = spec.find(':', start);
    out.push_back(spec.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

std::vector<std::string_view> split_fields(std::string_view fields) {
  std::vector<std::string_view> out;
  while (!fields.empty()) {
    const std::size_t end = fields.find("; ");
    out.push_back(fields.substr(0, end));
    if (end == std::string_view::npos) break;
    fields.remove_prefix(end + 2);
  }
  return out;
}

Result<std::string> parse_side(std::string_view spec, std::string_view field) {
  if (field != "left" && field != "right") return bad(spec, "SIDE: expected left or right");
  return std::string(field);
}

Result<double> parse_number(std::string_view spec, std::string_view field, double lo, double hi,
                            const std::string& what) {
  const std::string number(field);
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(v) || v < lo || v > hi)
    return bad(spec, what);
  return v;
}

std::size_t find_lung(const BakedAsset& a, const std::string& name) {
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    if (a.lungs[l].name == name) return l;
  return a.lungs.size();
}

Result<std::size_t> lung_of(const BakedAsset& a, const std::string& side, std::string_view spec) {
  const std::size_t l = find_lung(a, side);
  if (l == a.lungs.size()) return bad(spec, "the asset has no lung named '" + side + "'");
  return l;
}

double swept(const BakedAsset& a, const BakedLung& lung, const std::vector<float>& f) {
  const std::uint32_t c = a.coefficients();
  double sum = 0;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    double d = 0;
    for (std::uint32_t k = 0; k < c; ++k) d += double{a.sh_coeffs[i * c + k]} * f[k];
    sum += a.areas[i] * vec3(&a.directions[3 * i]).dot(vec3(&a.normals[3 * i])) * d;
  }
  return sum;
}

std::pair<double, double> extent(const BakedAsset& a, const BakedLung& lung, int axis) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    lo = std::min(lo, double{a.positions[3 * i + axis]});
    hi = std::max(hi, double{a.positions[3 * i + axis]});
  }
  return {lo, hi};
}

double midline_x(const BakedAsset& a) {
  double x = 0, shares = 0;
  for (const BakedLung& lung : a.lungs) {
    x += lung.volume_share * lung.centre[0];
    shares += lung.volume_share;
  }
  return shares > 0 ? x / shares : 0.0;
}

void keep_healthy_volumes(const BakedLung& lung, LungState& now) {
  if (!now.healthy_volumes)
    now.healthy_volumes = {lung.volume_const, lung.volume_grad[0], lung.volume_grad[1], lung.volume_grad[2]};
}

void resum_swept_volumes(const BakedAsset& a, BakedLung& lung, double before) {
  if (!(before > 0)) return;
  const double factor = lung.volume_const / before;
  lung.volume_const = factor * swept(a, lung, lung.force_const);
  for (int k = 0; k < 3; ++k) lung.volume_grad[k] = factor * swept(a, lung, lung.force_grad[k]);
}

Eigen::Vector3d hilum(const BakedAsset& a, std::size_t l) {
  const BakedLung& lung = a.lungs[l];
  const Eigen::Vector3d medial = medial_direction(lung.name, lung.centre[0], midline_x(a));
  const auto [lo, hi] = extent(a, lung, 2);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double area = 0;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    const double z = a.positions[3 * i + 2];
    if (z < lo + (hi - lo) / 3 || z > hi - (hi - lo) / 3 || vec3(&a.normals[3 * i]).dot(medial) < 0.5) continue;
    sum += a.areas[i] * vec3(&a.positions[3 * i]);
    area += a.areas[i];
  }
  return area > 0 ? Eigen::Vector3d(sum / area) : vec3(lung.centre.data());
}

void scale_about_hilum(BakedAsset& a, PatientState& patient, std::size_t l, double volume_factor) {
  BakedLung& lung = a.lungs[l];
  const double s = std::cbrt(volume_factor);
  const Eigen::Vector3d h = hilum(a, l);
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    for (int k = 0; k < 3; ++k) a.positions[3 * i + k] = static_cast<float>(h[k] + s * (a.positions[3 * i + k] - h[k]));
    a.areas[i] = static_cast<float>(a.areas[i] * s * s);
  }
  for (int k = 0; k < 3; ++k) lung.centre[k] = static_cast<float>(h[k] + s * (lung.centre[k] - h[k]));
  lung.rest_volume_ml *= s * s * s;
  lung.volume_const *= s * s;
  for (double& v : lung.volume_grad) v *= s * s;
  if (std::optional<std::array<double, 4>>& healthy = patient.lungs[l].healthy_volumes)
    for (double& v : *healthy) v *= s * s;
}

void scale_along_axis(BakedAsset& a, std::size_t l, int axis, double about, double k) {
  BakedLung& lung = a.lungs[l];
  const double before = swept(a, lung, lung.force_const);
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    a.positions[3 * i + axis] = static_cast<float>(about + k * (a.positions[3 * i + axis] - about));
    Eigen::Vector3d n = vec3(&a.normals[3 * i]);
    const double nu = n[axis];
    a.areas[i] = static_cast<float>(a.areas[i] * std::sqrt(nu * nu + k * k * (1.0 - nu * nu)));
    n *= k;
    n[axis] = nu;
    n.normalize();
    for (int c = 0; c < 3; ++c) a.normals[3 * i + c] = static_cast<float>(n[c]);
  }
  lung.centre[axis] = static_cast<float>(about + k * (lung.centre[axis] - about));
  lung.rest_volume_ml *= k;
  resum_swept_volumes(a, lung, before);
}

void scale_response(BakedAsset& a, std::size_t i, float m) {
  const std::uint32_t c = a.coefficients();
  for (std::uint32_t k = 0; k < c; ++k) a.sh_coeffs[i * c + k] *= m;
  if (!a.linear_coeffs.empty())
    for (int k = 0; k < 4; ++k) a.linear_coeffs[4 * i + k] *= m;
  if (a.has_off_axis())
    for (int k = 0; k < 12; ++k) a.off_axis[12 * i + k] *= m;
}

}  // namespace lungar::sim::pathology
