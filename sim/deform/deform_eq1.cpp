/// @file deform_eq1.cpp
/// @brief Eq. (1) through an Eigen Map over the asset's CSR rows (no copy).
#include "sim/deform/deform_eq1.h"

#include <Eigen/SparseCore>
#include <cassert>
#include <cstdint>

#include "sim/deform/deform_eq7.h"
#include "sim/force/dependent_collapse.h"
#include "sim/force/breath_share.h"
#include "sim/force/force_sh.h"

namespace lungar::sim {

void applied_force(const BakedAsset& asset, const PatientState& patient, const Eigen::Vector3d& g,
                   std::span<float> force_out) {
  // ARDS: the pressure falls beyond the collapse plane g . x = t (sim/force/dependent_collapse.h).
  const DependentCollapse* collapse = patient.lungs.empty() ? nullptr : patient.lungs.front().collapse.get();
  const double t = collapse ? collapse->threshold_mm(g) : 0.0;
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) {
    const BakedLung& lung = asset.lungs[l];
    const LungState& now = patient.lungs.at(l);
    const double scale = 1000.0 / swept_volume_mm3(asset, now, g);
    const double cg = g.x() * now.centre[0] + g.y() * now.centre[1] + g.z() * now.centre[2];
    for (std::size_t j = lung.first_vertex; j < std::size_t{lung.first_vertex} + lung.vertex_count; ++j) {
      const float* x = asset.positions.data() + 3 * j;
      const double depth = g.x() * x[0] + g.y() * x[1] + g.z() * x[2];
      double p = asset.p0 + asset.gamma_per_mm * (depth - cg);
      if (collapse) p *= DependentCollapse::pressure_factor(depth - t);
      force_out[j] = static_cast<float>(asset.areas[j] * p * scale);
    }
  }
}

void displacement_eq1(const BakedAsset& asset, std::span<const float> force, std::span<float> d_out) {
  assert(asset.has_transfer_rows());
  const auto n = static_cast<Eigen::Index>(asset.vertex_count());
  // Signed and unsigned 32-bit integers may alias; Eigen wants signed indices. The loader checked < 2^31.
  const Eigen::Map<const Eigen::SparseMatrix<float, Eigen::RowMajor, std::int32_t>> t(
      n, n, static_cast<Eigen::Index>(asset.transfer_vals.size()),
      reinterpret_cast<const std::int32_t*>(asset.transfer_row_ptr.data()),
      reinterpret_cast<const std::int32_t*>(asset.transfer_cols.data()), asset.transfer_vals.data());
  const Eigen::Map<const Eigen::VectorXf> f(force.data(), n);
  Eigen::Map<Eigen::VectorXf> d(d_out.data(), n);
  d.noalias() = t * f;  // eq. (1)
}

Eq1Deformer::Eq1Deformer(const BakedAsset& asset)
    : asset_(asset), force_(asset.vertex_count()), d_(asset.vertex_count()) {}

void Eq1Deformer::deform(const PatientState& patient, const Eigen::Vector3d& g, double delta_volume_ml,
                         std::span<float> positions_out) {
  applied_force(asset_, patient, g, force_);
  displacement_eq1(asset_, force_, d_);
  for (std::size_t l = 0; l < asset_.lungs.size(); ++l) {
    const BakedLung& lung = asset_.lungs[l];
    const auto scale = static_cast<float>(delta_volume_ml * breath_share(asset_, patient, l, g));
    const std::array<float, 4> w = linear_weights(asset_, patient.lungs[l], g);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      for (int k = 0; k < 3; ++k)
        positions_out[3 * i + k] = asset_.positions[3 * i + k] + scale * d_[i] * asset_.directions[3 * i + k];
      add_off_axis(asset_, i, w, scale, &positions_out[3 * i]);
    }
  }
}

}  // namespace lungar::sim
