/// @file ventral_share.cpp
/// @brief The anterior half's share of a breath (ventral_share.h).
#include "sim/motion/ventral_share.h"

#include <algorithm>

#include "sim/force/breath_share.h"
#include "sim/force/force_sh.h"

namespace lungar::sim {

VentralShare::VentralShare(const BakedAsset& a) {
  const std::uint32_t c = a.coefficients();
  const std::size_t n = a.vertex_count();
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    lo = std::min(lo, double{a.positions[3 * i + 1]});
    hi = std::max(hi, double{a.positions[3 * i + 1]});
  }
  const double middle = 0.5 * (lo + hi);
  for (const BakedLung& lung : a.lungs) {
    Sums front{std::vector<double>(c, 0.0), {}}, all{std::vector<double>(c, 0.0), {}};
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const float* nrm = &a.normals[3 * i];
      const float* dir = &a.directions[3 * i];
      const double along = a.areas[i] * (nrm[0] * dir[0] + nrm[1] * dir[1] + nrm[2] * dir[2]);
      const bool anterior = a.positions[3 * i + 1] < middle;
      for (std::uint32_t k = 0; k < c; ++k) {
        const double v = along * a.sh_coeffs[i * c + k];
        all.sh[k] += v;
        if (anterior) front.sh[k] += v;
      }
      if (!a.has_off_axis()) continue;
      const float* r = &a.off_axis[12 * i];
      for (int k = 0; k < 4; ++k) {
        const double v = a.areas[i] * (nrm[0] * r[k] + nrm[1] * r[4 + k] + nrm[2] * r[8 + k]);
        all.off_axis[k] += v;
        if (anterior) front.off_axis[k] += v;
      }
    }
    anterior_.push_back(std::move(front));
    whole_.push_back(std::move(all));
  }
}

double VentralShare::share(const BakedAsset& a, const PatientState& patient, std::span<const float> force,
                           const Eigen::Vector3d& g) const {
  const std::uint32_t c = a.coefficients();
  double front = 0, all = 0;
  for (std::size_t l = 0; l < a.lungs.size() && l < anterior_.size(); ++l) {
    const double s = breath_share(a, patient, l, g);
    const std::array<float, 4> w = linear_weights(a, patient.lungs[l], g);
    const auto swept = [&](const Sums& sums) {
      double v = 0;
      for (std::uint32_t k = 0; k < c; ++k) v += sums.sh[k] * force[l * c + k];
      for (int k = 0; k < 4; ++k) v += sums.off_axis[k] * w[k];
      return s * v;
    };
    front += swept(anterior_[l]);
    all += swept(whole_[l]);
  }
  return all != 0 ? front / all : 0.0;
}

}  // namespace lungar::sim
