/// @file lung_shapes.cpp
/// @brief The per-lung affine fit between two states of the same bake, and the blend.
#include "sim/pathology/lung_shapes.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "sim/force/dependent_collapse.h"

namespace lungar::sim {

namespace {

/// Points of each lung the map is fitted at and checked on: its LOD prefix, an even subsample of the surface.
constexpr std::size_t kFitPoints = 4096;
/// Largest distance (mm) between the fitted map of a loaded point and its changed position: above it the change
/// is not a map of the shape.
constexpr double kAffineToleranceMm = 0.05;

bool same_layout(const BakedAsset& a, const BakedAsset& b) {
  if (a.lungs.size() != b.lungs.size() || a.vertex_count() != b.vertex_count()) return false;
  for (std::size_t l = 0; l < a.lungs.size(); ++l)
    if (a.lungs[l].first_vertex != b.lungs[l].first_vertex || a.lungs[l].vertex_count != b.lungs[l].vertex_count)
      return false;
  return true;
}

/// Whether lung l's per-vertex response and force pattern are the same in both (a change of shape only).
bool same_response(const BakedAsset& a, const BakedAsset& b, std::size_t l) {
  const BakedLung& lung = a.lungs[l];
  const std::size_t c = a.coefficients();
  const auto first = static_cast<std::ptrdiff_t>(std::size_t{lung.first_vertex} * c);
  const auto count = static_cast<std::ptrdiff_t>(std::size_t{lung.vertex_count} * c);
  const auto severity = [](const BakedLung& x) { return x.collapse ? x.collapse->severity() : -1.0; };
  return std::equal(a.sh_coeffs.begin() + first, a.sh_coeffs.begin() + first + count, b.sh_coeffs.begin() + first) &&
         severity(a.lungs[l]) == severity(b.lungs[l]);
}

}  // namespace

Result<std::vector<LungShape>> lung_shapes(const BakedAsset& loaded, const BakedAsset& changed) {
  if (!same_layout(loaded, changed)) return fail("lung shapes: expected two states of the same bake");
  std::vector<LungShape> out;
  for (std::size_t l = 0; l < loaded.lungs.size(); ++l) {
    const BakedLung& before = loaded.lungs[l];
    const BakedLung& after = changed.lungs[l];
    if (!same_response(loaded, changed, l))
      return fail("lung '" + before.name + "': its response changed, not only its shape");
    const std::size_t n = std::min<std::size_t>(kFitPoints, before.vertex_count);
    Eigen::MatrixXd from(static_cast<Eigen::Index>(n), 4), to(static_cast<Eigen::Index>(n), 3);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = before.first_vertex + k;
      const auto row = static_cast<Eigen::Index>(k);
      from.row(row) << loaded.positions[3 * i], loaded.positions[3 * i + 1], loaded.positions[3 * i + 2], 1.0;
      to.row(row) << changed.positions[3 * i], changed.positions[3 * i + 1], changed.positions[3 * i + 2];
    }
    const Eigen::MatrixXd x = (from.transpose() * from).ldlt().solve(from.transpose() * to);  // 4 x 3
    const double worst = ((from * x) - to).rowwise().norm().maxCoeff();
    if (!(worst <= kAffineToleranceMm))
      return fail("lung '" + before.name + "': its new shape is not a map of its loaded one (" + std::to_string(worst) +
                  " mm off)");
    LungShape s;
    s.from_loaded.linear() = x.topRows(3).transpose();
    s.from_loaded.translation() = x.row(3).transpose();
    s.centre = after.centre;
    s.rest_volume_ml = after.rest_volume_ml;
    s.volume_const = after.volume_const;
    s.volume_grad = after.volume_grad;
    s.breath_weight = after.breath_weight;
    s.healthy_volumes = after.healthy_volumes;
    out.push_back(s);
  }
  return out;
}

std::vector<LungShape> blend(const std::vector<LungShape>& from, const std::vector<LungShape>& to, double w) {
  w = std::clamp(w, 0.0, 1.0);
  const auto mix = [w](double a, double b) { return a + w * (b - a); };
  std::vector<LungShape> out = w < 0.5 ? from : to;  // what does not blend (the healthy volumes) switches halfway
  for (std::size_t l = 0; l < out.size() && l < from.size() && l < to.size(); ++l) {
    LungShape& s = out[l];
    s.from_loaded.matrix() = from[l].from_loaded.matrix() + w * (to[l].from_loaded.matrix() - from[l].from_loaded.matrix());
    for (int k = 0; k < 3; ++k) s.centre[k] = static_cast<float>(mix(from[l].centre[k], to[l].centre[k]));
    s.rest_volume_ml = mix(from[l].rest_volume_ml, to[l].rest_volume_ml);
    s.volume_const = mix(from[l].volume_const, to[l].volume_const);
    for (int k = 0; k < 3; ++k) s.volume_grad[k] = mix(from[l].volume_grad[k], to[l].volume_grad[k]);
    s.breath_weight = mix(from[l].breath_weight, to[l].breath_weight);
  }
  return out;
}

void take_figures(const std::vector<LungShape>& shapes, BakedAsset& asset) {
  for (std::size_t l = 0; l < shapes.size() && l < asset.lungs.size(); ++l) {
    BakedLung& lung = asset.lungs[l];
    const LungShape& s = shapes[l];
    lung.centre = s.centre;
    lung.rest_volume_ml = s.rest_volume_ml;
    lung.volume_const = s.volume_const;
    lung.volume_grad = s.volume_grad;
    lung.breath_weight = s.breath_weight;
    lung.healthy_volumes = s.healthy_volumes;
  }
}

}  // namespace lungar::sim
