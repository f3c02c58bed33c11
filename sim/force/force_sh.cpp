/// @file force_sh.cpp
/// @brief Exact force SH from the four baked SH vectors, and the paper's angle interpolation.
#include "sim/force/force_sh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/force/dependent_collapse.h"

namespace lungar::sim {

EulerXYZ euler_xyz(const Eigen::Quaterniond& q) {
  const double norm = q.norm();
  if (!(norm > 0) || !std::isfinite(norm)) return {};
  const Eigen::Matrix3d r = Eigen::Quaterniond(q.coeffs() / norm).toRotationMatrix();
  auto wrap = [](double angle) {
    const double two_pi = 2 * std::numbers::pi;
    angle = std::fmod(angle, two_pi);
    return angle < 0 ? angle + two_pi : angle;
  };
  EulerXYZ out;
  out.b = wrap(std::asin(std::clamp(-r(2, 0), -1.0, 1.0)));
  out.a = wrap(std::atan2(r(2, 1), r(2, 2)));
  out.c = wrap(std::atan2(r(1, 0), r(0, 0)));
  return out;
}

double swept_volume_mm3(const BakedAsset& asset, const LungState& lung, const Eigen::Vector3d& g) {
  if (lung.collapse) return lung.collapse->lung_force(asset, lung.collapse_index, g).swept_mm3;
  return asset.p0 * lung.volume_const +
         asset.gamma_per_mm * (g.x() * lung.volume_grad[0] + g.y() * lung.volume_grad[1] + g.z() * lung.volume_grad[2]);
}

std::array<float, 4> linear_weights(const BakedAsset& asset, const LungState& lung, const Eigen::Vector3d& g) {
  if (lung.collapse) {
    const CollapsedLungForce f = lung.collapse->lung_force(asset, lung.collapse_index, g);
    const double scale = 1000.0 / f.swept_mm3;
    return {static_cast<float>(f.linear[0] * scale), static_cast<float>(f.linear[1] * scale),
            static_cast<float>(f.linear[2] * scale), static_cast<float>(f.linear[3] * scale)};
  }
  const double scale = 1000.0 / swept_volume_mm3(asset, lung, g);
  const double gamma = asset.gamma_per_mm * scale;
  return {static_cast<float>(asset.p0 * scale), static_cast<float>(gamma * g.x()), static_cast<float>(gamma * g.y()),
          static_cast<float>(gamma * g.z())};
}

void force_sh_exact(const BakedAsset& asset, const BakedLung& lung, const LungState& now, const Eigen::Vector3d& g,
                    float* out) {
  if (now.collapse) {
    const CollapsedLungForce f = now.collapse->lung_force(asset, now.collapse_index, g);
    const double scale = 1000.0 / f.swept_mm3;
    for (std::size_t i = 0; i < f.sh.size(); ++i) out[i] = static_cast<float>(f.sh[i] * scale);
    return;
  }
  const double scale = 1000.0 / swept_volume_mm3(asset, now, g);  // mm^3 per mL
  const double a = asset.p0 * scale, gx = asset.gamma_per_mm * g.x() * scale,
               gy = asset.gamma_per_mm * g.y() * scale, gz = asset.gamma_per_mm * g.z() * scale;
  const std::size_t n = lung.force_const.size();
  for (std::size_t i = 0; i < n; ++i)
    out[i] = static_cast<float>(a * lung.force_const[i] + gx * lung.force_grad[0][i] + gy * lung.force_grad[1][i] +
                                gz * lung.force_grad[2][i]);
}

void force_sh_paper(const BakedLung& lung, std::uint32_t coefficients, const Eigen::Quaterniond& q, float* out) {
  const EulerXYZ angles = euler_xyz(q);
  const double step = std::numbers::pi / 2;
  std::fill(out, out + coefficients, 0.0f);
  const double per_axis[kPaperAxes] = {angles.a, angles.b, angles.c};
  for (int axis = 0; axis < kPaperAxes; ++axis) {
    const double angle = per_axis[axis];
    // Lower and upper baked angles around `angle`; baked index k holds (k + 1) * pi/2, and 0 is 2pi.
    const int lower_k = std::clamp(static_cast<int>(std::floor(angle / step)), 0, kPaperAngles - 1);
    const double a0 = lower_k * step, a1 = a0 + step;
    const int i0 = lower_k == 0 ? kPaperAngles - 1 : lower_k - 1;
    const int i1 = lower_k;
    const double w0 = std::cos(angle - a0) / 3.0, w1 = std::cos(angle - a1) / 3.0;
    const auto& p0 = lung.paper_force[axis * kPaperAngles + i0];
    const auto& p1 = lung.paper_force[axis * kPaperAngles + i1];
    for (std::uint32_t i = 0; i < coefficients; ++i) out[i] += static_cast<float>(w0 * p0[i] + w1 * p1[i]);
  }
}

void force_sh(const BakedAsset& asset, const PatientState& patient, ForceMode mode, const Eigen::Quaterniond& q,
              float* out) {
  const std::uint32_t c = asset.coefficients();
  const Eigen::Vector3d g = gravity_in_lung_frame(q);
  for (std::size_t l = 0; l < asset.lungs.size(); ++l) {
    if (mode == ForceMode::Exact)
      force_sh_exact(asset, asset.lungs[l], patient.lungs.at(l), g, out + l * c);
    else force_sh_paper(asset.lungs[l], c, q, out + l * c);
  }
}

}  // namespace lungar::sim
