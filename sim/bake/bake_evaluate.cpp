/// @file bake_evaluate.cpp
/// @brief RMS relative errors over all vertices and the 26 report directions, alpha, the bands sweep, and the
///        tidal-volume, base/apex and posterior/anterior figures.
#include "sim/bake/bake_evaluate.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <thread>

#include "sim/deform/deform_eq1.h"
#include "sim/deform/deform_eq7.h"
#include "sim/force/force_sh.h"
#include "sim/sh/real_sh.h"

namespace lungar::sim {
namespace {

/// Accumulates sum (approx - exact)^2, sum exact^2, and the cross terms for alpha.
struct ErrorSum {
  double diff2 = 0, exact2 = 0, cross = 0, approx2 = 0;
  void add(double approx, double exact) {
    diff2 += (approx - exact) * (approx - exact);
    exact2 += exact * exact;
    cross += approx * exact;
    approx2 += approx * approx;
  }
  double rms_rel() const { return exact2 > 0 ? std::sqrt(diff2 / exact2) : 0.0; }
  double alpha() const { return approx2 > 0 ? cross / approx2 : 0.0; }  // least squares: exact ~ alpha approx
};

/// The orientation (lung frame in world) of least rotation that makes g the lung-frame gravity.
Eigen::Quaterniond orientation_for(const Eigen::Vector3d& g) {
  return Eigen::Quaterniond::FromTwoVectors(g, Eigen::Vector3d(0, 0, -1));
}

/// Mean displacement over vertices in the top and bottom `fraction` of each lung's extent along `axis`.
double end_ratio(const BakedAsset& a, const std::vector<float>& d, int axis, double fraction) {
  double high_sum = 0, low_sum = 0;
  std::size_t high_n = 0, low_n = 0;
  for (const BakedLung& lung : a.lungs) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      lo = std::min<double>(lo, a.positions[3 * i + axis]);
      hi = std::max<double>(hi, a.positions[3 * i + axis]);
    }
    const double band = fraction * (hi - lo);
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i) {
      const double x = a.positions[3 * i + axis];
      const double v = d[i] * lung.volume_share;
      if (x >= hi - band) { high_sum += v; ++high_n; }
      if (x <= lo + band) { low_sum += v; ++low_n; }
    }
  }
  if (high_n == 0 || low_n == 0 || low_sum == 0) return 0;
  return (high_sum / high_n) / (low_sum / low_n);  // high end over low end
}

}  // namespace

void evaluate_bake(const std::vector<std::unique_ptr<LungWork>>& work, const BakedAsset& a, const BakeOptions& opt,
                   int threads, const BakeProgress& progress, BakeReport& report) {
  const std::vector<Eigen::Vector3d> dirs = report_directions();
  const auto nd = static_cast<Eigen::Index>(dirs.size());
  const std::size_t n = a.vertex_count();
  Eigen::MatrixXd g_mat(3, nd);
  for (Eigen::Index k = 0; k < nd; ++k) g_mat.col(k) = dirs[k];

  // The exact eq. (1), D = K^-1 (A o p_g) / V(g) * 1000. p is linear in g, so in exact arithmetic this is
  // p0 tau0 + gamma tau g from the double-precision solves (no rounding to float, unlike the asset's linear
  // basis); tests check it against fresh solves.
  Eigen::MatrixXd exact(n, nd);
  std::vector<Eigen::MatrixXd> pressures;  // per lung, N x nd
  std::vector<Eigen::RowVectorXd> scales;  // per lung, 1000 / V(g)
  for (std::size_t l = 0; l < work.size(); ++l) {
    const LungWork& w = *work[l];
    const BakedLung& lung = a.lungs[l];
    Eigen::MatrixXd p = (w.offsets * g_mat * opt.gamma_per_mm).array() + opt.p0;
    const Eigen::MatrixXd d = (w.x.col(w.c_solved) * opt.p0).replicate(1, nd) +
                              opt.gamma_per_mm * w.x.middleCols(w.c_solved + 1, 3) * g_mat;
    Eigen::RowVectorXd s(nd);
    for (Eigen::Index k = 0; k < nd; ++k) s[k] = 1000.0 / swept_volume_mm3(a, lung, dirs[k]);
    exact.middleRows(lung.first_vertex, lung.vertex_count) = d * s.asDiagonal();
    pressures.push_back(std::move(p));
    scales.push_back(std::move(s));
    if (progress) progress("evaluate", 0.3 * (l + 1) / work.size());
  }

  // Through the float asset, as the runtime computes it.
  ErrorSum eq7, paper, linear, eq1;
  const std::uint32_t c = a.coefficients();
  std::vector<float> force(a.lungs.size() * c), paper_force(a.lungs.size() * c);
  std::vector<float> d7(n), dp(n), dl(n), d1(n), f1(n);
  for (Eigen::Index k = 0; k < nd; ++k) {
    const Eigen::Vector3d& g = dirs[k];
    for (std::size_t l = 0; l < a.lungs.size(); ++l) force_sh_exact(a, a.lungs[l], g, force.data() + l * c);
    force_sh(a, ForceMode::paper, orientation_for(g), paper_force.data());
    displacement_eq7(a, force, d7);
    displacement_eq7(a, paper_force, dp);
    displacement_linear(a, g, dl);
    if (a.has_transfer_rows()) {
      applied_force(a, g, f1);
      displacement_eq1(a, f1, d1);
    }
    for (std::size_t i = 0; i < n; ++i) {
      eq7.add(d7[i], exact(i, k));
      paper.add(dp[i], d7[i]);
      linear.add(dl[i], exact(i, k));
      if (a.has_transfer_rows()) eq1.add(d1[i], exact(i, k));
    }
  }
  report.gravity_directions = static_cast<std::uint32_t>(nd);
  report.eq7_rms_rel_error = eq7.rms_rel();
  report.alpha = eq7.alpha();
  report.paper_interp_rms_rel_error = paper.rms_rel();
  report.linear_basis_rms_rel_error = linear.rms_rel();
  report.eq1_truncated_rms_rel_error = a.has_transfer_rows() ? eq1.rms_rel() : 0.0;
  if (progress) progress("evaluate", 0.6);

  // Bands sweep in double precision: the projection with the leading L^2 x L^2 block of G; one thread a lung.
  const int max_bands = opt.bands_sweep ? kMaxBands : 1;
  std::vector<std::vector<ErrorSum>> sweep(work.size(), std::vector<ErrorSum>(max_bands + 1));
  auto sweep_lung = [&](std::size_t l) {
    const LungWork& w = *work[l];
    const BakedLung& lung = a.lungs[l];
    const Eigen::MatrixXd weighted = w.areas.asDiagonal() * pressures[l];
    for (int bands = 2; bands <= max_bands && bands * bands <= w.c_solved; ++bands) {
      const int cb = bands * bands;
      const Eigen::LDLT<Eigen::MatrixXd> gram(w.gram.topLeftCorner(cb, cb));
      const Eigen::MatrixXd f = gram.solve(w.y.leftCols(cb).transpose() * weighted);
      const Eigen::MatrixXd d = (w.x.leftCols(cb) * f) * scales[l].asDiagonal();
      for (Eigen::Index k = 0; k < nd; ++k)
        for (Eigen::Index i = 0; i < d.rows(); ++i) sweep[l][bands].add(d(i, k), exact(lung.first_vertex + i, k));
    }
  };
  {
    std::vector<std::thread> pool;
    for (std::size_t l = 1; l < work.size(); ++l) {
      if (threads > 1) pool.emplace_back(sweep_lung, l);
      else sweep_lung(l);
    }
    sweep_lung(0);
    for (auto& t : pool) t.join();
  }
  for (int bands = 2; bands <= max_bands && bands * bands <= work.front()->c_solved; ++bands) {
    ErrorSum e;
    for (const auto& per_lung : sweep) {
      e.diff2 += per_lung[bands].diff2;
      e.exact2 += per_lung[bands].exact2;
    }
    report.bands_sweep.push_back(
        {static_cast<std::uint32_t>(bands), static_cast<std::uint32_t>(bands * bands), e.rms_rel()});
  }
  if (progress) progress("evaluate", 0.9);

  // Physiology at the tidal volume: upright and supine, through eq. (7).
  constexpr double kTidalMl = kTidalVolumeMl;
  const Eigen::Vector3d upright(0, 0, -1), supine_g(0, 1, 0);
  for (std::size_t l = 0; l < a.lungs.size(); ++l) force_sh_exact(a, a.lungs[l], upright, force.data() + l * c);
  displacement_eq7(a, force, d7);
  double max_mm = 0;
  for (const BakedLung& lung : a.lungs)
    for (std::size_t i = lung.first_vertex; i < std::size_t{lung.first_vertex} + lung.vertex_count; ++i)
      max_mm = std::max(max_mm, std::abs(d7[i] * kTidalMl * lung.volume_share));
  report.displacement_max_mm_at_tidal = max_mm;
  std::vector<float> displaced(3 * n);
  deform_eq7(a, force, kTidalMl, displaced);
  std::vector<Triangle> tris(a.triangles.size() / 3);
  for (std::size_t t = 0; t < tris.size(); ++t) tris[t] = {a.triangles[3 * t], a.triangles[3 * t + 1], a.triangles[3 * t + 2]};
  const double rest = enclosed_volume(tris, a.positions.data()), moved = enclosed_volume(tris, displaced.data());
  report.tidal_volume_rel_error = ((moved - rest) / 1000.0 - kTidalMl) / kTidalMl;
  const double apex_base = end_ratio(a, d7, 2, 0.15);  // apex is high z
  report.base_apex_displacement_ratio = apex_base > 0 ? 1.0 / apex_base : 0.0;
  for (std::size_t l = 0; l < a.lungs.size(); ++l) force_sh_exact(a, a.lungs[l], supine_g, force.data() + l * c);
  displacement_eq7(a, force, d7);
  report.posterior_anterior_displacement_ratio = end_ratio(a, d7, 1, 0.15);  // posterior is high y
  report.evaluated = true;
  if (progress) progress("evaluate", 1.0);
}

}  // namespace lungar::sim
