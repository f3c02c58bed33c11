/// @file dependent_collapse.cpp
/// @brief ARDS's gravity-dependent force: the collapse plane, and the pattern's SH and linear fits per posture.
#include "sim/force/dependent_collapse.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "sim/sh/real_sh.h"

namespace lungar::sim {

namespace {

Eigen::Vector3d unit_or_upright(const Eigen::Vector3d& g) {
  const double n = g.norm();
  return std::isfinite(n) && n > 0 ? Eigen::Vector3d(g / n) : Eigen::Vector3d(0, 0, -1);
}

/// sum_I A_I (n_I . e_I) T^I_lm over the lung: the first-order swept volume of D = f . T^I along e_I per unit f_lm.
Eigen::VectorXd volume_per_sh(const BakedAsset& a, const BakedLung& lung) {
  const std::uint32_t c = a.coefficients();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(c);
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    const float* n = &a.normals[3 * i];
    const float* e = &a.directions[3 * i];
    const double along = a.areas[i] * (n[0] * e[0] + n[1] * e[1] + n[2] * e[2]);
    for (std::uint32_t k = 0; k < c; ++k) v[k] += along * a.sh_coeffs[i * c + k];
  }
  return v;
}

/// sum_I A_I n_I . r_I^j: the swept volume of the off-axis part per unit linear weight j (0 without one).
Eigen::Vector4d volume_per_linear(const BakedAsset& a, const BakedLung& lung) {
  Eigen::Vector4d v = Eigen::Vector4d::Zero();
  if (!a.has_off_axis()) return v;
  for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
    const float* n = &a.normals[3 * i];
    const float* r = &a.off_axis[12 * i];
    for (int j = 0; j < 4; ++j) v[j] += a.areas[i] * (n[0] * r[j] + n[1] * r[4 + j] + n[2] * r[8 + j]);
  }
  return v;
}

/// (Phi^T W Phi)^-1 Phi^T W: the area-weighted least-squares fit of values at the samples onto the columns of Phi.
Eigen::MatrixXd weighted_fit(const Eigen::MatrixXd& phi, const Eigen::VectorXd& w) {
  const Eigen::MatrixXd weighted = phi.transpose() * w.asDiagonal();
  return (weighted * phi).ldlt().solve(weighted);
}

}  // namespace

Result<std::shared_ptr<const DependentCollapse>> DependentCollapse::build(const BakedAsset& a, double severity) {
  if (!a.has_sphere_dirs())
    return fail("the asset holds no sphere points (it was baked before asset format 3): re-bake it with this "
                "lungar-bake to project a force that follows the posture");
  auto out = std::make_shared<DependentCollapse>();
  out->severity_ = severity;
  const int bands = static_cast<int>(a.bands);
  const std::uint32_t c = a.coefficients();
  for (const BakedLung& lung : a.lungs) {
    const std::size_t k_count = std::min<std::size_t>(kSamplesPerLung, lung.vertex_count);
    if (k_count < std::size_t{c} + 4) return fail("lung '" + lung.name + "' has too few vertices to fit its force");
    Samples s;
    s.centre = Eigen::Vector3d(lung.centre[0], lung.centre[1], lung.centre[2]);
    s.positions.resize(static_cast<Eigen::Index>(k_count), 3);
    s.normals.resize(static_cast<Eigen::Index>(k_count), 3);
    Eigen::MatrixXd y(static_cast<Eigen::Index>(k_count), c), phi(static_cast<Eigen::Index>(k_count), 4);
    double lung_area = 0;
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i)
      lung_area += a.areas[i];
    // The LOD prefix is an even (Poisson-disk) subsample of the surface: each sample stands for an equal area.
    s.weights = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(k_count), lung_area / static_cast<double>(k_count));
    Eigen::VectorXd sh(c);
    for (std::size_t k = 0; k < k_count; ++k) {
      const std::size_t i = lung.first_vertex + k;
      const auto row = static_cast<Eigen::Index>(k);
      for (int d = 0; d < 3; ++d) {
        s.positions(row, d) = a.positions[3 * i + d];
        s.normals(row, d) = a.normals[3 * i + d];
      }
      const Eigen::Vector3d u(a.sphere_dirs[3 * i], a.sphere_dirs[3 * i + 1], a.sphere_dirs[3 * i + 2]);
      real_sh(bands, u.normalized(), sh.data());
      y.row(row) = sh.transpose();
      phi.row(row) << 1.0, (s.positions.row(row) - s.centre.transpose());
    }
    s.sh_fit = weighted_fit(y, s.weights);
    s.linear_fit = weighted_fit(phi, s.weights);
    s.volume_sh = volume_per_sh(a, lung);
    s.volume_linear = volume_per_linear(a, lung);
    Eigen::VectorXd f0(c);
    for (std::uint32_t k = 0; k < c; ++k) f0[k] = lung.force_const[k];
    const double first_order = f0.dot(s.volume_sh) + s.volume_linear[0];
    if (!(first_order > 0)) return fail("lung '" + lung.name + "' sweeps no volume under a uniform pressure");
    s.calibration = lung.volume_const / first_order;
    out->lungs_.push_back(std::move(s));
  }
  return std::shared_ptr<const DependentCollapse>(std::move(out));
}

double DependentCollapse::collapsed_share(const Eigen::Vector3d& g) const {
  const Eigen::Vector3d u = unit_or_upright(g);
  return std::clamp(severity_ * (kCollapseMid + kCollapseTilt * u.y()), 0.0, 0.95);
}

double DependentCollapse::threshold_mm(const Eigen::Vector3d& g) const {
  const Eigen::Vector3d u = unit_or_upright(g);
  // Every sample's depth along g and its area-weighted facing, once: the bisection only sums them.
  std::size_t count = 0;
  for (const Samples& s : lungs_) count += static_cast<std::size_t>(s.positions.rows());
  Eigen::VectorXd depth(static_cast<Eigen::Index>(count)), facing(static_cast<Eigen::Index>(count));
  Eigen::Index at = 0;
  for (const Samples& s : lungs_) {
    const Eigen::Index n = s.positions.rows();
    depth.segment(at, n) = s.positions * u;
    facing.segment(at, n) = s.weights.cwiseProduct(s.normals * u);
    at += n;
  }
  double lo = depth.minCoeff(), hi = depth.maxCoeff();
  // The pair's volume beyond the plane g . x = t, from the surface alone (see the header).
  auto beyond = [&](double t) { return ((depth.array() - t).max(0.0) * facing.array()).sum(); };
  const double target = collapsed_share(u) * beyond(lo);
  if (!(target > 0)) return hi + kCollapseRampMm;  // nothing collapsed: every point well before the plane
  // 30 halvings of the lungs' depth (some 300 mm): the plane to under a micrometre.
  for (int iteration = 0; iteration < 30; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (beyond(mid) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double DependentCollapse::pressure_factor(double beyond_mm) {
  const double x = std::clamp(beyond_mm / kCollapseRampMm + 0.5, 0.0, 1.0);
  return 1.0 - (1.0 - kCollapsedPressure) * x * x * (3.0 - 2.0 * x);
}

CollapsedLungForce DependentCollapse::lung_force(const BakedAsset& a, std::size_t lung, const Eigen::Vector3d& g) const {
  const Eigen::Vector3d u = unit_or_upright(g);
  std::lock_guard lock(cache_mutex_);
  if (cached_.size() == lungs_.size() && u == cached_g_) return cached_.at(lung);
  const double t = threshold_mm(u);
  cached_.clear();
  for (const Samples& s : lungs_) {
    const Eigen::VectorXd depth = s.positions * u;
    const double centre_depth = u.dot(s.centre);
    Eigen::VectorXd p(depth.size());
    for (Eigen::Index k = 0; k < depth.size(); ++k)
      p[k] = (a.p0 + a.gamma_per_mm * (depth[k] - centre_depth)) * pressure_factor(depth[k] - t);
    CollapsedLungForce f;
    const Eigen::VectorXd sh = s.sh_fit * p;
    f.sh.assign(sh.data(), sh.data() + sh.size());
    const Eigen::Vector4d linear = s.linear_fit * p;
    for (int j = 0; j < 4; ++j) f.linear[j] = linear[j];
    f.swept_mm3 = s.calibration * (sh.dot(s.volume_sh) + linear.dot(s.volume_linear));
    cached_.push_back(std::move(f));
  }
  cached_g_ = u;
  return cached_.at(lung);
}

CollapseFitError DependentCollapse::fit_error(const BakedAsset& a, const Eigen::Vector3d& g) const {
  const Eigen::Vector3d u = unit_or_upright(g);
  const double t = threshold_mm(u);
  const int bands = static_cast<int>(a.bands);
  Eigen::VectorXd y(a.coefficients());
  double sh2 = 0, linear2 = 0, exact2 = 0;
  for (std::size_t l = 0; l < a.lungs.size() && l < lungs_.size(); ++l) {
    const BakedLung& lung = a.lungs[l];
    const CollapsedLungForce f = lung_force(a, l, u);
    const Eigen::Map<const Eigen::VectorXd> sh(f.sh.data(), static_cast<Eigen::Index>(f.sh.size()));
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const Eigen::Vector3d x(a.positions[3 * i], a.positions[3 * i + 1], a.positions[3 * i + 2]);
      const Eigen::Vector3d offset = x - lungs_[l].centre;
      const double p = (a.p0 + a.gamma_per_mm * u.dot(offset)) * pressure_factor(u.dot(x) - t);
      real_sh(bands, Eigen::Vector3d(a.sphere_dirs[3 * i], a.sphere_dirs[3 * i + 1], a.sphere_dirs[3 * i + 2]).normalized(),
              y.data());
      const double by_sh = sh.dot(y);
      const double by_line = f.linear[0] + f.linear[1] * offset.x() + f.linear[2] * offset.y() + f.linear[3] * offset.z();
      sh2 += a.areas[i] * (by_sh - p) * (by_sh - p);
      linear2 += a.areas[i] * (by_line - p) * (by_line - p);
      exact2 += a.areas[i] * p * p;
    }
  }
  if (!(exact2 > 0)) return {};
  return {std::sqrt(sh2 / exact2), std::sqrt(linear2 / exact2)};
}

}  // namespace lungar::sim
