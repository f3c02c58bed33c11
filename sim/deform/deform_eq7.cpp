/// @file deform_eq7.cpp
/// @brief Eq. (7) as one Eigen matrix-vector product per lung (vectorised), then the move along each vertex's direction.
#include "sim/deform/deform_eq7.h"

#include <Eigen/Core>
#include <cassert>

#include "sim/force/breath_share.h"
#include "sim/force/force_sh.h"

namespace lungar::sim {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

void displacement_eq7(const BakedAsset& asset, std::span<const float> force_sh, std::span<float> d_out) {
  const Eigen::Index c = asset.coefficients();
  assert(force_sh.size() >= asset.lungs.size() * c && d_out.size() >= asset.vertex_count());
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) {
    const BakedLung& lung = asset.lungs[l];
    const Eigen::Map<const RowMatrix> t(asset.sh_coeffs.data() + std::size_t{lung.first_vertex} * c,
                                        lung.vertex_count, c);
    const Eigen::Map<const Eigen::VectorXf> f(force_sh.data() + l * c, c);
    Eigen::Map<Eigen::VectorXf> d(d_out.data() + lung.first_vertex, lung.vertex_count);
    d.noalias() = t * f;  // eq. (7), alpha = 1
  }
}

void deform_eq7(const BakedAsset& asset, const PatientState& patient, std::span<const float> force_sh,
                const Eigen::Vector3d& g, double delta_volume_ml, std::span<float> positions_out) {
  const std::size_t c = asset.coefficients();
  assert(positions_out.size() >= 3 * std::size_t{asset.vertex_count()});
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) {
    const BakedLung& lung = asset.lungs[l];
    const auto scale = static_cast<float>(delta_volume_ml * breath_share(asset, patient, l, g));
    const std::array<float, 4> w = linear_weights(asset, patient.lungs[l], g);
    const Eigen::Map<const Eigen::VectorXf> f(force_sh.data() + l * c, static_cast<Eigen::Index>(c));
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const Eigen::Map<const Eigen::VectorXf> t(asset.sh_coeffs.data() + i * c, static_cast<Eigen::Index>(c));
      const float move = scale * t.dot(f);
      for (int k = 0; k < 3; ++k) positions_out[3 * i + k] = asset.positions[3 * i + k] + move * asset.directions[3 * i + k];
      add_off_axis(asset, i, w, scale, &positions_out[3 * i]);
    }
  }
}

void displacement_linear(const BakedAsset& asset, const PatientState& patient, const Eigen::Vector3d& g,
                         std::span<float> d_out) {
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) {
    const BakedLung& lung = asset.lungs[l];
    const std::array<float, 4> w = linear_weights(asset, patient.lungs.at(l), g);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const float* tau = asset.linear_coeffs.data() + 4 * i;
      d_out[i] = w[0] * tau[0] + w[1] * tau[1] + w[2] * tau[2] + w[3] * tau[3];
    }
  }
}

}  // namespace lungar::sim
