/// @file lesion_rows.cpp
/// @brief Summing a lesion's surface weights into its rows, and evaluating them (lesion_rows.h).
#include "sim/motion/lesion_rows.h"

#include <cassert>

namespace lungar::sim {

std::vector<LesionRows> lesion_rows(const BakedAsset& asset, const InteriorDisplacement& field,
                                    const std::vector<PlacedLesion>& lesions) {
  const std::size_t c = asset.coefficients();
  std::vector<LesionRows> out;
  for (const PlacedLesion& placed : lesions) {
    LesionRows rows;
    rows.placed = placed;
    std::vector<double> a(3 * c, 0.0);
    std::array<double, 12> b{};
    for (const VertexWeight& e : field.surface_weights(placed.lesion.centre_mm, placed.lung)) {
      const std::size_t i = e.vertex;
      for (int k = 0; k < 3; ++k) {
        const double along = e.weight * asset.directions[3 * i + static_cast<std::size_t>(k)];
        for (std::size_t lm = 0; lm < c; ++lm)
          a[static_cast<std::size_t>(k) * c + lm] += along * asset.sh_coeffs[i * c + lm];
      }
      if (asset.has_off_axis())
        for (std::size_t j = 0; j < 12; ++j) b[j] += e.weight * asset.off_axis[12 * i + j];
    }
    rows.sh.assign(a.begin(), a.end());
    for (std::size_t j = 0; j < 12; ++j) rows.off_axis[j] = static_cast<float>(b[j]);
    out.push_back(std::move(rows));
  }
  return out;
}

Eigen::Vector3d LesionRows::displacement(std::span<const float> force, const std::array<float, 4>& w,
                                         double dv_ml) const {
  const std::size_t c = force.size();
  assert(sh.size() == 3 * c);  // rows of the asset whose force this is (Runtime::create checks it)
  Eigen::Vector3d u;
  for (std::size_t k = 0; k < 3; ++k) {
    double sum = 0;
    for (std::size_t lm = 0; lm < c; ++lm) sum += double{sh[k * c + lm]} * force[lm];
    for (std::size_t j = 0; j < 4; ++j) sum += double{off_axis[4 * k + j]} * w[j];
    u[static_cast<Eigen::Index>(k)] = sum;
  }
  return dv_ml * u;
}

}  // namespace lungar::sim
