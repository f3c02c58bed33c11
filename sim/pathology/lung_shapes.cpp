/// @file lung_shapes.cpp
/// @brief The per-lung affine fit between two states of the same bake, and the blend.
#include "sim/pathology/lung_shapes.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <string>


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

/// Whether lung l's per-vertex response is the same in both (a change of shape or of the force only).
bool same_response(const BakedAsset& a, const BakedAsset& b, std::size_t l) {
  const BakedLung& lung = a.lungs[l];
  const std::size_t c = a.coefficients();
  const auto first = static_cast<std::ptrdiff_t>(std::size_t{lung.first_vertex} * c);
  const auto count = static_cast<std::ptrdiff_t>(std::size_t{lung.vertex_count} * c);
  return std::equal(a.sh_coeffs.begin() + first, a.sh_coeffs.begin() + first + count, b.sh_coeffs.begin() + first);
}

}  // namespace

Result<std::vector<LungShape>> lung_shapes(const BakedAsset& loaded, const BakedAsset& changed,
                                           const PatientState& changed_patient) {
  if (!same_layout(loaded, changed) || changed_patient.lungs.size() != changed.lungs.size())
    return fail("lung shapes: expected two states of the same bake");
  std::vector<LungShape> out;
  for (std::size_t l = 0; l < loaded.lungs.size(); ++l) {
    const BakedLung& before = loaded.lungs[l];
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
    s.figures = changed_patient.lungs[l];
    out.push_back(s);
  }
  return out;
}

std::vector<LungShape> blend(const std::vector<LungShape>& from, const std::vector<LungShape>& to, double w) {
  w = std::clamp(w, 0.0, 1.0);
  const auto mix = [w](double a, double b) { return a + w * (b - a); };
  std::vector<LungShape> out = w < 0.5 ? from : to;  // what does not blend switches halfway
  for (std::size_t l = 0; l < out.size() && l < from.size() && l < to.size(); ++l) {
    out[l].from_loaded.matrix() =
        from[l].from_loaded.matrix() + w * (to[l].from_loaded.matrix() - from[l].from_loaded.matrix());
    LungState& f = out[l].figures;
    const LungState &a = from[l].figures, &b = to[l].figures;
    for (int k = 0; k < 3; ++k) f.centre[k] = static_cast<float>(mix(a.centre[k], b.centre[k]));
    f.rest_volume_ml = mix(a.rest_volume_ml, b.rest_volume_ml);
    f.volume_const = mix(a.volume_const, b.volume_const);
    for (int k = 0; k < 3; ++k) f.volume_grad[k] = mix(a.volume_grad[k], b.volume_grad[k]);
    f.breath_weight = mix(a.breath_weight, b.breath_weight);
  }
  return out;
}

}  // namespace lungar::sim
